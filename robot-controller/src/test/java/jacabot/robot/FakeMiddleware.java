package jacabot.robot;

import jacabot.robot.link.Command;
import jacabot.robot.link.CommandWriter;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorDataReader;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorInfoFilter;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Arrays;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/** A bare middleware for the controller's tests, written against the shared protocol classes only. */
final class FakeMiddleware implements AutoCloseable {
    private final ServerSocket server;
    /** The key the controllers started by {@link #startController} share with this middleware. */
    final LinkSecret secret = LinkSecret.random();

    FakeMiddleware() throws IOException {
        server = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        server.setSoTimeout(10_000);
    }

    int port() {
        return server.getLocalPort();
    }

    /** Starts a controller of the navigation world's robot, pointed at this middleware, stepping on its own thread. */
    RobotController startController(ControllerConfig config) throws Exception {
        return startController(config, false);
    }

    /** As {@link #startController(ControllerConfig)}, in a pipelined lockstep when {@code pipelined}. */
    RobotController startController(ControllerConfig config, boolean pipelined) throws Exception {
        var controller = new RobotController(RobotControllerTest.world("navigation"),
                config.withAddress("127.0.0.1", port()).withSecret(secret)).pipelined(pipelined);
        controller.start();
        controller.runner().start();
        return controller;
    }

    /** Stops a controller from {@link #startController}, then this middleware. */
    void stop(RobotController controller) throws Exception {
        controller.close();
        controller.runner().stop();
        close();
    }

    /**
     * Accepts a controller and answers its handshake with {@code version}: for this version, the
     * whole authenticated handshake with {@link #secret}; for another, a refusal.
     */
    Peer accept(int version) throws IOException {
        return accept(version, secret);
    }

    /** Accepts a controller, proving {@code key} (the controller's own secret or not). */
    Peer accept(int version, LinkSecret key) throws IOException {
        Socket s = server.accept();
        var in = new DataInputStream(s.getInputStream());
        var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
        if (version == Protocol.VERSION) {
            Protocol.Hello hello;
            try {
                hello = Handshake.asMiddleware(in, out, key);
            } catch (IOException e) {
                s.close();
                throw e;
            }
            return new Peer(s, hello, out);
        }
        var hello = Protocol.Hello.read(in);
        String mismatch = Protocol.versionMismatch(hello.version(), version);
        new Protocol.Welcome(version, mismatch == null, mismatch == null ? "welcome" : mismatch).write(out);
        return new Peer(s, hello, out);
    }

    @Override
    public void close() throws IOException {
        server.close();
    }

    /** One accepted controller: its frames arrive in {@link #frames}. */
    static final class Peer implements AutoCloseable {
        final Socket socket;
        final Protocol.Hello hello;
        final OutputStream raw;
        final CommandWriter commands;
        final BlockingQueue<Uplink> frames = new LinkedBlockingQueue<>();
        private int seq;

        Peer(Socket socket, Protocol.Hello hello, OutputStream out) {
            this.socket = socket;
            this.hello = hello;
            this.raw = out;
            this.commands = new CommandWriter(out);
            Thread t = new Thread(() -> {
                try {
                    var reader = new SensorDataReader(socket.getInputStream(), SensorInfoFilter.Limits.DEFAULT);
                    Uplink f;
                    while ((f = reader.read()) != null) {
                        frames.add(f);
                    }
                } catch (IOException e) {
                    // the test closed it
                }
            });
            t.setDaemon(true);
            t.start();
        }

        void send(Command c) throws IOException {
            commands.write(++seq, 0, c);
        }

        /** {@return the first frame matching, waiting up to 10 s} */
        Uplink await(Predicate<Uplink> p) throws InterruptedException {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (System.nanoTime() < end) {
                Uplink f = frames.poll(100, TimeUnit.MILLISECONDS);
                if (f != null && p.test(f)) {
                    return f;
                }
            }
            throw new AssertionError("no matching frame within 10 s");
        }

        /** Waits for the marker of lockstep step {@code step}. */
        Uplink.StepMarker awaitMarker(long step) throws InterruptedException {
            return (Uplink.StepMarker) await(f -> f instanceof Uplink.StepMarker && ((Uplink.StepMarker) f).step() == step);
        }

        /** Waits for a batch whose wheel speeds reading is (left, right). */
        Uplink.Batch awaitWheels(double left, double right) throws InterruptedException {
            return (Uplink.Batch) await(f -> f instanceof Uplink.Batch && ((Uplink.Batch) f).readings().stream()
                    .anyMatch(i -> i.getId() == SensorKind.WHEEL_SPEEDS.id()
                            && Arrays.equals(i.getDoubleValues(), new double[] {left, right})));
        }

        static double value(Uplink.Batch b, SensorKind kind) {
            return b.readings().stream().filter(i -> i.getId() == kind.id()).mapToDouble(SensorInfo::getVal)
                    .findFirst().orElse(Double.NaN);
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
