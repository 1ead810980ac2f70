package jacabot.app.run;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.concurrent.Semaphore;
import java.util.function.Consumer;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLServerSocket;
import javax.net.ssl.SSLSocket;

/**
 * TLS in front of a middleware that listens on loopback ({@code jacabot run --tls-store}): accepts
 * TLS connections on the public address and relays their bytes, both ways, to the middleware. The
 * link's own handshake (the shared secret) goes through it end to end, so the middleware still
 * decides who drives; the relay only adds encryption on the network path. At most
 * {@link #MAX_CONNECTIONS} relayed at once; a TLS handshake must be done within 2 s.
 */
public final class TlsRelay implements AutoCloseable {
    static final int MAX_CONNECTIONS = 16;
    private static final int HANDSHAKE_MS = 2000;

    private final SSLServerSocket server;
    private final int target;
    private final Consumer<String> log;
    private final Semaphore slots = new Semaphore(MAX_CONNECTIONS);
    private volatile boolean closed;

    private TlsRelay(SSLServerSocket server, int target, Consumer<String> log) {
        this.server = server;
        this.target = target;
        this.log = log;
    }

    /** Listens with TLS on {@code address:port} (0: a free port) and relays to 127.0.0.1:{@code target}. */
    public static TlsRelay start(SSLContext tls, InetAddress address, int port, int target, Consumer<String> log)
            throws IOException {
        var server = (SSLServerSocket) tls.getServerSocketFactory().createServerSocket();
        try {
            server.bind(new InetSocketAddress(address, port), 16);
        } catch (IOException e) {
            server.close();
            throw e;
        }
        TlsRelay relay = new TlsRelay(server, target, log);
        Thread t = new Thread(relay::acceptLoop, "tls-relay");
        t.setDaemon(true);
        t.start();
        return relay;
    }

    /** {@return the port the relay listens on} */
    public int port() {
        return server.getLocalPort();
    }

    private void acceptLoop() {
        while (!closed) {
            Socket outer;
            try {
                outer = server.accept();
            } catch (IOException e) {
                if (!closed) {
                    log.accept("tls relay: " + e.getMessage());
                }
                continue;
            }
            if (!slots.tryAcquire()) {
                closeQuietly(outer);
                continue;
            }
            Thread t = new Thread(() -> relay((SSLSocket) outer), "tls-relay-connection");
            t.setDaemon(true);
            t.start();
        }
    }

    private void relay(SSLSocket outer) {
        try (outer) {
            outer.setSoTimeout(HANDSHAKE_MS);
            outer.startHandshake(); // before the middleware hears of it
            outer.setSoTimeout(0); // the middleware's own deadlines hold from here
            try (Socket inner = new Socket(InetAddress.getLoopbackAddress(), target)) {
                outer.setTcpNoDelay(true);
                inner.setTcpNoDelay(true);
                Thread up = new Thread(() -> pump(outer, inner), "tls-relay-up");
                up.setDaemon(true);
                up.start();
                pump(inner, outer);
                up.join();
            }
        } catch (IOException e) {
            log.accept("tls relay: connection from " + outer.getInetAddress().getHostAddress() + " closed: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            slots.release();
        }
    }

    /** Copies until either side ends, then closes both (the other pump ends with it). */
    private static void pump(Socket from, Socket to) {
        byte[] buf = new byte[16384];
        try {
            InputStream in = from.getInputStream();
            OutputStream out = to.getOutputStream();
            int n;
            while ((n = in.read(buf)) >= 0) {
                out.write(buf, 0, n);
                out.flush();
            }
        } catch (IOException e) {
            // one side went: both close below
        } finally {
            closeQuietly(from);
            closeQuietly(to);
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException e) {
            // closing anyway
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            server.close();
        } catch (IOException e) {
            // closing anyway
        }
    }
}
