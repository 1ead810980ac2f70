package jacabot.experiments;

import static jacabot.experiments.link.LinkTestSupport.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import jacabot.cartago.Workspace;
import jacabot.experiments.link.RawFrames;
import jacabot.robot.link.CommandCode;
import jacabot.robot.link.CommandReader;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkClock;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.ReceivedCommand;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/**
 * The middleware artifact in socket mode (the two-process set-up) against a controller that holds
 * the secret and sends what the test wants: a malformed reading does not end the serving loop, the
 * agent is told {@code failsafe(tripped)}, and a lockstep step is acknowledged.
 */
class ArtifactSocketModeTest {
    @Test
    void theServingLoopSurvivesBadReadingsTellsTheFailSafeAndAcknowledgesSteps() throws Exception {
        LinkSecret secret = LinkSecret.random();
        LinkSecret.useInThisProcess(secret);
        List<String> signals = new CopyOnWriteArrayList<>();
        Map<String, Object> properties = new ConcurrentHashMap<>();
        try (Workspace ws = Workspace.builder("main").build()) {
            AgentId agent = ws.join("robot", new ArtifactObserverAdapter() {
                @Override
                public void focused(ArtifactId a, List<PropertySnapshot> ps) {
                    ps.forEach(p -> properties.put(p.name(), p.values().size() == 1 ? p.value() : p.values()));
                }

                @Override
                public void propertyUpdated(ArtifactId a, PropertySnapshot old, PropertySnapshot now) {
                    properties.put(now.name(), now.values().size() == 1 ? now.value() : now.values());
                }

                @Override
                public void signalled(ArtifactId a, String type, List<Object> args) {
                    signals.add(type + args);
                }
            });
            ArtifactId id = ws.createArtifact("middleware", ObjectPickingMiddleware.class.getName(), 0);
            int port = ws.artifactObject(id, MiddlewareArtifact.class).orElseThrow().link().port();
            ws.execOp(agent, OpTarget.any(), "focus", new Object[] {id}, o -> { });
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                Handshake.asController(new DataInputStream(s.getInputStream()), out,
                        new Protocol.Hello(Protocol.VERSION, "khepera", "w", 40, true), secret);
                ws.execOp(agent, OpTarget.id(id), "accept", new Object[0], o -> { });
                ws.execOp(agent, OpTarget.id(id), "acquireData", new Object[0], o -> { });
                waitFor(() -> Boolean.TRUE.equals(properties.get("connected")));
                var frames = new ObjectOutputStream(new BufferedOutputStream(s.getOutputStream()));
                // a gripper reading with an empty array: it used to kill the serving loop
                RawFrames.batch(frames, 0, new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[0]));
                RawFrames.batch(frames, 1, new SensorInfo(SensorKind.GRIP_PRESENCE.id(), 1.0));
                frames.writeByte(Uplink.STEP_MARKER);
                frames.writeLong(1);
                frames.writeLong(40);
                frames.writeBoolean(true);
                frames.writeByte(Uplink.FAIL_SAFE);
                frames.writeLong(40);
                frames.writeUTF("test: no heartbeat");
                frames.flush();
                waitFor(() -> signals.contains("failsafe[TRIPPED]") || signals.stream().anyMatch(x -> x.startsWith("failsafe")));
                var reader = new CommandReader(s.getInputStream(), LinkClock.system());
                ReceivedCommand ack;
                do {
                    ack = reader.read();
                } while (ack != null && ack.command() != null && ack.command().code() == CommandCode.HEARTBEAT);
                assertTrue(ack != null && ack.command() != null, String.valueOf(ack));
                assertEquals(CommandCode.STEP_ACK, ack.command().code(), "the lockstep step was acknowledged");
                assertEquals(1.0, ack.command().arg(0));
                assertEquals(Boolean.TRUE, properties.get("connected"), "still serving after the bad reading");
            }
        } finally {
            LinkSecret.resetUserDefault();
        }
    }
}
