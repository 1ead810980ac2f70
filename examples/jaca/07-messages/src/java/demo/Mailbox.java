package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.IBlockingCmd;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;

/**
 * A UDP mailbox on the loopback interface, at a port the system picks (observable as port(P)).
 * A datagram carries "senderPort|text".
 */
public class Mailbox extends Artifact {
    private DatagramSocket socket;

    /** Waits for one datagram; the socket is closed by dispose, which ends the wait. */
    private final class Receive implements IBlockingCmd {
        String text;
        String from;

        @Override
        public void exec() {
            byte[] buffer = new byte[2048];
            DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
            try {
                socket.receive(packet);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            String data = new String(packet.getData(), 0, packet.getLength(), StandardCharsets.UTF_8);
            int bar = data.indexOf('|');
            from = "localhost:" + data.substring(0, bar);
            text = data.substring(bar + 1);
        }
    }

    void init() throws IOException {
        socket = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        defineObsProperty("port", socket.getLocalPort());
    }

    @OPERATION
    void send(String text, String to) throws IOException {
        String[] hostPort = to.split(":");
        byte[] data = (socket.getLocalPort() + "|" + text).getBytes(StandardCharsets.UTF_8);
        socket.send(new DatagramPacket(data, data.length,
                new InetSocketAddress(InetAddress.getLoopbackAddress(), Integer.parseInt(hostPort[1]))));
    }

    @OPERATION
    void receive(OpFeedbackParam<String> text, OpFeedbackParam<String> from) {
        Receive r = new Receive();
        await(r);
        text.set(r.text);
        from.set(r.from);
    }

    @OPERATION
    void startReceiving() {
        execInternalOp("receiving");
    }

    @INTERNAL_OPERATION
    void receiving() {
        while (true) {
            Receive r = new Receive();
            await(r);
            signal("new_msg", r.text, r.from);
        }
    }

    @Override
    protected void dispose() {
        socket.close();
    }
}
