package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.LineReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** await(IBlockingCmd) on a loopback socket leaves the artifact usable. */
class BlockingCommandTest {
    @Test
    void otherOperationsRunWhileTheReaderBlocksOnTheSocket() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            CompletableFuture<Integer> port = new CompletableFuture<>();
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("robot", new ArtifactObserverAdapter() {
                @Override
                public void focused(ArtifactId artifact, List<PropertySnapshot> properties) {
                    port.complete((Integer) properties.get(0).value());
                    obs.focused(artifact, properties);
                }

                @Override
                public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
                    obs.propertyUpdated(artifact, oldValue, newValue);
                }

                @Override
                public void signalled(ArtifactId artifact, String type, List<Object> args) {
                    obs.signalled(artifact, type, args);
                }
            });
            ArtifactId reader = Calls.makeArtifact(ws, agent, "reader", LineReader.class);
            ok(ws, agent, "focus", reader);
            obs.next();
            ok(ws, agent, "serve");
            // The loop now blocks in accept(): the artifact still answers.
            assertEquals("pong", ok(ws, agent, "ping", new OpFeedbackParam<>()).outputs().get(0));

            try (Socket client = new Socket(InetAddress.getLoopbackAddress(), port.get(10, TimeUnit.SECONDS));
                    Writer out = new OutputStreamWriter(client.getOutputStream(), StandardCharsets.UTF_8)) {
                obs.expect("reader !connected");
                // The loop now blocks in readLine(), which nothing has been written for.
                assertEquals("pong", ok(ws, agent, "ping", new OpFeedbackParam<>()).outputs().get(0));
                out.write("hello\nworld\n");
                out.flush();
                obs.expect("reader last(\"\")->last(\"hello\")", "reader !received[hello]",
                        "reader last(\"hello\")->last(\"world\")", "reader !received[world]");
            }
            obs.expect("reader !closed");
            assertTrue(ws.lookup("reader").isPresent());
        }
    }

    @Test
    void disposingTheArtifactReleasesABlockedCommand() throws Exception {
        RecordingLogger log = new RecordingLogger();
        try (Workspace ws = Workspace.builder("main").logger(log).build()) {
            AgentId agent = ws.join("robot", new RecordingObserver());
            ArtifactId reader = Calls.makeArtifact(ws, agent, "reader", LineReader.class);
            ok(ws, agent, "serve");
            ok(ws, agent, "disposeArtifact", reader);
            assertTrue(ws.lookup("reader").isEmpty());
            // The loop blocked in accept() resumes with the socket closed and fails as disposed.
            assertEquals("warning reader: internal operation reader.readLoop() failed: artifact reader was disposed",
                    log.next());
            assertEquals(List.of("workspace", "console", "blackboard", "body_robot"),
                    ws.artifacts().stream().map(ArtifactId::name).collect(Collectors.toList()));
        }
    }
}
