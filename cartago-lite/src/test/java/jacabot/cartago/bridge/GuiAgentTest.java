package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import jacabot.agent.parser.AslParser;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Clock;
import jacabot.cartago.NumberPanel;
import jacabot.cartago.Workspace;
import java.awt.event.InputEvent;
import java.awt.event.MouseEvent;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/**
 * CArtAgO's GUI example (07a) without its window: a free-running agent focuses a GUI artifact
 * whose components get real Swing events on the event dispatch thread; the agent perceives the
 * property and the signals these events cause, and answers the ok button through an operation.
 */
class GuiAgentTest {
    private static final String AGENT = """
            !start.
            +!start <- makeArtifact("panel", "jacabot.cartago.NumberPanel", [], Id); focus(Id).
            +value(V) <- .print("value ", V).
            +ok : value(V) <- setValue(V + 1).
            +dragged(X, Y) <- .print("dragged to ", X, ",", Y).
            """;

    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();

    private List<String> lines() {
        return bytes.toString(StandardCharsets.UTF_8).lines().toList();
    }

    /** Waits until the agent has printed {@code line} (a safety net of 20 s, not a timing assumption). */
    private void waitFor(String line) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 20_000;
        while (!lines().contains(line)) {
            if (System.currentTimeMillis() > deadline) {
                fail("the agent never printed \"" + line + "\"; it printed " + lines());
            }
            Thread.sleep(10);
        }
    }

    @Test
    void anAgentPerceivesWhatTheButtonTheKeyAndTheMouseDo() throws Exception {
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        LocalMAS mas = new LocalMAS(Clock.wall(), out, 7);
        Workspace ws = Workspace.builder("main").console(out).build();
        CartagoEnvironment env = new CartagoEnvironment(ws);
        mas.setEnvironment(env, List.of());
        AslParser parser = new AslParser();
        mas.createAgent("gui_user", parser.parse(AGENT, "gui_user.asl"), parser, CAgentArch::new);
        Thread runner = new Thread(() -> {
            try {
                mas.runThreads();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "gui-mas");
        runner.start();
        try {
            waitFor("[gui_user] value 0");
            NumberPanel panel = ws.artifactObject(ws.lookup("panel").orElseThrow(), NumberPanel.class).orElseThrow();
            SwingUtilities.invokeAndWait(panel.ok::doClick);
            waitFor("[gui_user] value 1");
            SwingUtilities.invokeAndWait(() -> panel.field.enter("41"));
            waitFor("[gui_user] value 41");
            SwingUtilities.invokeAndWait(panel.ok::doClick);
            waitFor("[gui_user] value 42");
            SwingUtilities.invokeAndWait(() -> panel.pad.dispatchEvent(new MouseEvent(panel.pad, MouseEvent.MOUSE_DRAGGED,
                    System.currentTimeMillis(), InputEvent.BUTTON1_DOWN_MASK, 3, 4, 0, false)));
            waitFor("[gui_user] dragged to 3,4");
            assertEquals(List.of("[gui_user] value 0", "[gui_user] value 1", "[gui_user] value 41", "[gui_user] value 42",
                    "[gui_user] dragged to 3,4"), lines());
            assertEquals("42", panel.field.getText(), "the agent's setValue wrote the field");
        } finally {
            mas.stop();
            runner.join(5000);
            env.stop();
        }
    }
}
