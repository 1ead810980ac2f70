package jacabot.cartago.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.Artifact;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import jacabot.cartago.Workspace;
import jacabot.cartago.examples.Counter;
import java.io.ByteArrayInputStream;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** A workspace used from another "process" through the node's loopback service. */
class RemoteWorkspaceTest {
    private final WorkspaceSecret secret = WorkspaceSecret.random();
    private Workspace main;
    private WorkspaceServer server;

    /** An artifact whose operation throws. */
    public static class Faulty extends Artifact {
        @OPERATION
        void boom() {
            throw new IllegalStateException("broken on purpose");
        }

        @OPERATION
        void huge(OpFeedbackParam<String> out) {
            out.set("x".repeat(Wire.MAX_STRING + 1));
        }

        @OPERATION
        void give(OpFeedbackParam<Object> out) {
            out.set(new Object() {
                @Override
                public String toString() {
                    return "an object";
                }
            });
        }
    }

    @BeforeEach
    void start() throws Exception {
        main = Workspace.builder("main").logger(CartagoLogger.silent()).build();
        main.createArtifact("counter", Counter.class);
        main.createArtifact("faulty", Faulty.class);
        server = WorkspaceServer.start(0, name -> name.equals("main") ? Optional.of(main) : Optional.empty(), secret,
                CartagoLogger.silent());
    }

    @AfterEach
    void stop() {
        server.close();
        main.close();
    }

    private RemoteWorkspace join(String agent, Recorder r, WorkspaceSecret s) throws IOException {
        return RemoteWorkspace.join("127.0.0.1", server.port(), "main", agent, r, s);
    }

    private static OpOutcome call(RemoteWorkspace w, OpTarget target, String op, Object... args) throws Exception {
        var done = new CompletableFuture<OpOutcome>();
        w.execOp(target, op, args, done::complete);
        return done.get(10, TimeUnit.SECONDS);
    }

    static final class Recorder extends ArtifactObserverAdapter {
        final List<String> events = new CopyOnWriteArrayList<>();

        @Override
        public void focused(ArtifactId artifact, List<PropertySnapshot> properties) {
            events.add("focused " + artifact.name() + "@" + artifact.workspace() + " " + properties);
        }

        @Override
        public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
            events.add("updated " + newValue);
        }

        @Override
        public void focusEnded(ArtifactId artifact, List<PropertySnapshot> properties, boolean disposed) {
            events.add("ended " + artifact.name());
        }
    }

    @Test
    void operationsOutputsAndPerceptionCrossTheConnection() throws Exception {
        var r = new Recorder();
        RemoteWorkspace w = join("voyager", r, secret);
        var id = (ArtifactId) ((OpOutcome.Success) call(w, OpTarget.any(), "lookupArtifact", "counter",
                new OpFeedbackParam<>())).outputs().get(1);
        assertEquals("main@127.0.0.1:" + server.port(), id.workspace(), "the remote workspace's ids are its own");
        assertTrue(call(w, OpTarget.any(), "focus", id).succeeded());
        assertTrue(call(w, OpTarget.id(id), "inc").succeeded());
        assertTrue(main.agents().stream().anyMatch(a -> a.name().equals("voyager")));
        w.quit();
        assertEquals(List.of("focused counter@" + id.workspace() + " [count(0)]", "updated count(1)", "ended counter"),
                r.events);
        assertTrue(main.agents().stream().noneMatch(a -> a.name().equals("voyager")), "quitting leaves the workspace");
    }

    @Test
    void anExceptionInAnArtifactFailsTheOperationAndTheSessionGoesOn() throws Exception {
        RemoteWorkspace w = join("voyager", new Recorder(), secret);
        var f = assertInstanceOf(OpOutcome.Failure.class, call(w, OpTarget.name("faulty"), "boom"));
        assertEquals("exception", f.reasonFunctor());
        assertTrue(f.message().contains("broken on purpose"), f.message());
        // a result of a shape that may not cross arrives as its text
        assertEquals("an object", ((OpOutcome.Success) call(w, OpTarget.name("faulty"), "give",
                new OpFeedbackParam<>())).outputs().get(0));
        var tooBig = assertInstanceOf(OpOutcome.Failure.class, call(w, OpTarget.name("faulty"), "huge",
                new OpFeedbackParam<>()));
        assertEquals("not_transferable", tooBig.reasonFunctor());
        assertTrue(call(w, OpTarget.name("counter"), "inc").succeeded());
        w.close();
    }

    @Test
    void anArgumentOfAnotherShapeIsRefusedBeforeSending() throws Exception {
        RemoteWorkspace w = join("voyager", new Recorder(), secret);
        var f = assertInstanceOf(OpOutcome.Failure.class, call(w, OpTarget.any(), "inc", new Object()));
        assertEquals("bad_argument", f.reasonFunctor());
        assertEquals(List.of(1), f.reasonArgs());
        f = assertInstanceOf(OpOutcome.Failure.class, call(w, OpTarget.any(), "inc", 1,
                List.of(new AtomicLong(3))));
        assertEquals(List.of(2), f.reasonArgs(), "a Number of another class, inside a list");
        f = assertInstanceOf(OpOutcome.Failure.class, call(w, OpTarget.any(), "inc", "x".repeat(Wire.MAX_STRING + 1)));
        assertEquals("bad_argument", f.reasonFunctor());
        assertTrue(call(w, OpTarget.name("counter"), "inc").succeeded(), "nothing half-sent: the session goes on");
        w.close();
    }

    @Test
    void aClientWithoutTheSecretIsRefusedAndTheNodeServesOthers() throws Exception {
        var e = assertThrows(IOException.class, () -> join("stranger", new Recorder(), WorkspaceSecret.random()));
        assertTrue(e.getMessage().contains("secret"), e.getMessage());
        try (var garbage = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            OutputStream out = garbage.getOutputStream();
            out.write("GET / HTTP/1.0\r\n\r\n".getBytes());
            out.flush();
            garbage.setSoTimeout(10_000);
            assertEquals(-1, garbage.getInputStream().read(), "the node hangs up");
        }
        assertTrue(main.agents().stream().noneMatch(a -> a.name().equals("stranger")));
        RemoteWorkspace w = join("voyager", new Recorder(), secret);
        assertTrue(call(w, OpTarget.name("counter"), "inc").succeeded());
        w.close();
    }

    @Test
    void aWorkspaceTheNodeDoesNotHaveIsRefused() {
        var e = assertThrows(IOException.class,
                () -> RemoteWorkspace.join("127.0.0.1", server.port(), "attic", "voyager", new Recorder(), secret));
        assertEquals("no workspace attic on this node", e.getMessage());
    }

    @Test
    void readingAcceptsOnlyTheAllowedShapes() {
        for (byte[] forged : List.of(new byte[] {99}, new byte[] {7, 0x7f, 0, 0, 0}, new byte[] {6, 0x7f, 0, 0, 0})) {
            assertThrows(IOException.class, () -> Wire.read(new DataInputStream(new ByteArrayInputStream(forged)),
                    UnaryOperator.identity()));
        }
        byte[] deep = new byte[6 * 40 + 1];
        for (int i = 0; i < 40; i++) {
            deep[i * 5] = 7;
            deep[i * 5 + 4] = 1;   // a list of one element, nested 40 deep
        }
        assertThrows(IOException.class, () -> Wire.read(new DataInputStream(new ByteArrayInputStream(deep)),
                UnaryOperator.identity()));
    }

    @Test
    void aLostNodeEndsTheFocusAndTellsTheClient() throws Exception {
        var r = new Recorder();
        var lost = new CountDownLatch(1);
        RemoteWorkspace w = RemoteWorkspace.join("127.0.0.1", server.port(), "main", "voyager", r, secret, lost::countDown);
        var id = (ArtifactId) ((OpOutcome.Success) call(w, OpTarget.any(), "lookupArtifact", "counter",
                new OpFeedbackParam<>())).outputs().get(1);
        assertTrue(call(w, OpTarget.any(), "focus", id).succeeded());
        assertTrue(call(w, OpTarget.id(id), "inc").succeeded());
        server.close();
        assertTrue(lost.await(10, TimeUnit.SECONDS), "the lost callback ran");
        assertEquals("ended counter", r.events.get(r.events.size() - 1), r.events.toString());
        var f = assertInstanceOf(OpOutcome.Failure.class, call(w, OpTarget.id(id), "inc"));
        assertEquals("workspace_closed", f.reasonFunctor());
    }

    /**
     * A node that stops as the agent leaves (example 11's keeper ends its run on seeing the body
     * go) may close the connection before the focus-ended frame leaves its writer: on a loaded
     * machine the agent then kept the beliefs of an artifact it no longer focused. Here a node
     * that never sends that frame: the quit itself must end the focus.
     */
    @Test
    void aQuitEndsTheFocusEvenWhenTheNodeClosesWithoutSayingSo() throws Exception {
        try (var node = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            var id = new ArtifactId(7, "counter", Counter.class.getName(), "main", null);
            var served = CompletableFuture.runAsync(() -> {
                try (Socket c = node.accept()) {
                    var in = new DataInputStream(new BufferedInputStream(c.getInputStream()));
                    var out = new DataOutputStream(new BufferedOutputStream(c.getOutputStream()));
                    RemoteHandshake.asNode(in, out, secret);
                    assertEquals(Frames.JOIN, in.readUnsignedByte());
                    Wire.readString(in);
                    Wire.readString(in);
                    out.writeByte(Frames.JOINED);
                    out.writeBoolean(true);
                    Wire.writeString(out, "joined main");
                    out.writeByte(Frames.EVENT);
                    out.writeByte(Frames.FOCUSED);
                    Wire.write(out, id, UnaryOperator.identity());
                    Wire.writeProperties(out, List.of(new PropertySnapshot("count", List.of(3))), UnaryOperator.identity());
                    out.flush();
                    assertEquals(Frames.QUIT, in.readUnsignedByte());
                } catch (IOException e) {
                    throw new RuntimeException(e);
                }
            });
            var r = new Recorder();
            RemoteWorkspace w = RemoteWorkspace.join("127.0.0.1", node.getLocalPort(), "main", "voyager", r, secret);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (r.events.isEmpty() && System.nanoTime() < deadline) {
                Thread.sleep(5);   // until the focus arrived
            }
            w.quit();
            served.get(30, TimeUnit.SECONDS);
            assertEquals(List.of("focused counter@main@127.0.0.1:" + node.getLocalPort() + " [count(3)]", "ended counter"),
                    r.events);
        }
    }
}
