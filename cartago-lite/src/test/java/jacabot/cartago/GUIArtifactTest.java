package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import jacabot.cartago.tools.GUIArtifact;
import java.awt.Component;
import java.awt.GraphicsEnvironment;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.ItemEvent;
import java.awt.event.MouseEvent;
import java.awt.event.WindowEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JFrame;
import javax.swing.JList;
import javax.swing.JSlider;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.event.ChangeEvent;
import javax.swing.event.ListSelectionEvent;
import org.junit.jupiter.api.Test;

/**
 * Swing events of real components, fired on the event dispatch thread without a window (the
 * tests run without a display), reach the agents focusing a {@link GUIArtifact} as the
 * operations they are linked to.
 */
class GUIArtifactTest {
    /** Runs {@code action} on the event dispatch thread and waits for it. */
    static void onEdt(Runnable action) throws Exception {
        SwingUtilities.invokeAndWait(action);
    }

    static void drag(Component on, int x, int y) {
        on.dispatchEvent(new MouseEvent(on, MouseEvent.MOUSE_DRAGGED, System.currentTimeMillis(), InputEvent.BUTTON1_DOWN_MASK,
                x, y, 0, false));
    }

    private static final class Fixture implements AutoCloseable {
        final RecordingLogger log = new RecordingLogger();
        final Workspace ws = Workspace.builder("main").logger(log).build();
        final RecordingObserver obs = new RecordingObserver();
        final AgentId agent = ws.join("user", obs);

        <T extends Artifact> T make(String name, Class<T> type) {
            ArtifactId id = Calls.makeArtifact(ws, agent, name, type);
            ok(ws, agent, "focus", id);
            obs.next(); // focused
            return ws.artifactObject(id, type).orElseThrow();
        }

        @Override
        public void close() {
            ws.close();
        }
    }

    @Test
    void aClickAKeyAndADragBecomeTheirOperations() throws Exception {
        try (Fixture f = new Fixture()) {
            NumberPanel panel = f.make("panel", NumberPanel.class);
            onEdt(panel.ok::doClick);
            f.obs.expect("panel !ok");
            onEdt(() -> panel.field.enter("41"));
            f.obs.expect("panel value(0)->value(41)");
            onEdt(() -> drag(panel.pad, 5, 7));
            f.obs.expect("panel !dragged[5, 7]");
            // an agent's operation and the GUI's share the artifact
            ok(f.ws, f.agent, "setValue", 42);
            f.obs.expect("panel value(41)->value(42)");
            assertEquals("42", panel.field.getText());
        }
    }

    @Test
    void eventsWaitForABusyArtifactWithoutHoldingTheEventThreadAndRunInTheirOrder() throws Exception {
        try (Fixture f = new Fixture()) {
            NumberPanel panel = f.make("panel", NumberPanel.class);
            CompletableFuture<OpOutcome> held = Calls.start(f.ws, f.agent, OpTarget.any(), "hold");
            assertTrue(panel.holding.await(10, TimeUnit.SECONDS));
            // the event thread hands the events over and returns although the artifact is taken
            List<String> expected = new ArrayList<>();
            onEdt(() -> {
                for (int i = 1; i <= 20; i++) {
                    drag(panel.pad, i, 2 * i);
                    panel.ok.doClick();
                }
            });
            for (int i = 1; i <= 20; i++) {
                expected.add("panel !dragged[" + i + ", " + 2 * i + "]");
                expected.add("panel !ok");
            }
            assertEquals(List.of(), f.obs.drain(), "no event operation ran while hold() held the artifact");
            assertFalse(held.isDone());
            panel.release.countDown();
            assertTrue(held.get(10, TimeUnit.SECONDS).succeeded());
            List<String> seen = new ArrayList<>();
            for (int i = 0; i < expected.size(); i++) {
                seen.add(f.obs.next());
            }
            assertEquals(expected, seen, "one operation per event, in the order of the events");
        }
    }

    /** A gate: its pass button's operation has a guard, which its open button makes true. */
    public static class Gate extends GUIArtifact {
        final JButton pass = new JButton("pass");
        final JButton open = new JButton("open");
        final KeyField broken = new KeyField("", 4);
        private boolean isOpen;

        @Override
        public void setup() {
            defineObsProperty("passed", 0);
            linkActionEventToOp(pass, "passThrough");
            linkActionEventToOp(open, "openGate");
            linkKeyStrokeToOp(broken, "ENTER", "breakDown");
        }

        @GUARD
        boolean gateOpen(ActionEvent e) {
            return isOpen;
        }

        @INTERNAL_OPERATION(guard = "gateOpen")
        void passThrough(ActionEvent e) {
            getObsProperty("passed").updateValue(getObsProperty("passed").intValue() + 1);
        }

        @INTERNAL_OPERATION
        void openGate(ActionEvent e) {
            isOpen = true;
            signal("opened");
        }

        @INTERNAL_OPERATION
        void breakDown(ActionEvent e) {
            getObsProperty("passed").updateValue(-1);
            failed("broken on purpose");
        }
    }

    @Test
    void anOperationWaitingForItsGuardLetsTheNextEventsRun() throws Exception {
        try (Fixture f = new Fixture()) {
            Gate gate = f.make("gate", Gate.class);
            onEdt(gate.pass::doClick);
            onEdt(gate.open::doClick);
            f.obs.expect("gate !opened", "gate passed(0)->passed(1)");
        }
    }

    @Test
    void aFailingEventOperationIsRolledBackAndLoggedAndLaterEventsStillRun() throws Exception {
        try (Fixture f = new Fixture()) {
            Gate gate = f.make("gate", Gate.class);
            onEdt(() -> gate.broken.enter(""));
            assertEquals("warning gate: internal operation gate.handleGUIEvent(breakDown on keyStroke pressed ENTER) failed: "
                    + "broken on purpose", f.log.next());
            onEdt(gate.open::doClick);
            onEdt(gate.pass::doClick);
            // passed(-1) was rolled back: the observer sees 0 -> 1 only
            f.obs.expect("gate !opened", "gate passed(0)->passed(1)");
        }
    }

    /** One component of each other kind, and a custom link through the common listener. */
    public static class Controls extends GUIArtifact {
        final JCheckBox check = new JCheckBox("lights");
        final JComboBox<String> combo = new JComboBox<>(new String[] {"red", "green"});
        final JList<String> list = new JList<>(new String[] {"a", "b", "c"});
        final JSlider slider = new JSlider(0, 10, 0);
        final JTextField custom = new JTextField();

        @Override
        public void setup() {
            linkItemEventToOp(check, "toggled");
            linkActionEventToOp(combo, "chosen");
            linkListSelectionEventToOp(list, "selected");
            linkChangeEventToOp(slider, "slid");
            custom.addActionListener(getEventListenerInstance());
            insertEventToOp(custom, "actionPerformed", "customAction");
        }

        @INTERNAL_OPERATION
        void toggled(ItemEvent e) {
            signal("toggled", e.getStateChange() == ItemEvent.SELECTED);
        }

        @INTERNAL_OPERATION
        void chosen(ActionEvent e) {
            signal("chosen", combo.getSelectedItem());
        }

        @INTERNAL_OPERATION
        void selected(ListSelectionEvent e) {
            if (!e.getValueIsAdjusting()) {
                signal("selected", list.getSelectedValue());
            }
        }

        @OPERATION
        void slid(ChangeEvent e) {
            signal("slid", slider.getValue());
        }

        @INTERNAL_OPERATION
        void customAction() {
            signal("custom");
        }
    }

    @Test
    void everyKindOfLinkReachesItsOperation() throws Exception {
        try (Fixture f = new Fixture()) {
            Controls c = f.make("controls", Controls.class);
            onEdt(c.check::doClick);
            f.obs.expect("controls !toggled[true]");
            onEdt(() -> c.combo.setSelectedIndex(1));
            f.obs.expect("controls !chosen[green]");
            onEdt(() -> c.list.setSelectedIndex(2));
            f.obs.expect("controls !selected[c]");
            onEdt(() -> c.slider.setValue(7));
            f.obs.expect("controls !slid[7]");
            onEdt(c.custom::postActionEvent);
            f.obs.expect("controls !custom");
        }
    }

    @Test
    void inASteppedWorkspaceAnEventRunsAtARunPending() throws Exception {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("user", obs);
            ArtifactId id = Calls.makeArtifact(ws, agent, "panel", NumberPanel.class);
            ok(ws, agent, "focus", id);
            ws.runPending();
            obs.next(); // focused
            NumberPanel panel = ws.artifactObject(id, NumberPanel.class).orElseThrow();
            onEdt(panel.ok::doClick);
            Thread.sleep(200);
            assertEquals(List.of(), obs.drain(), "nothing runs between two runPending calls");
            long deadline = System.currentTimeMillis() + 10_000;
            while (obs.seen().size() < 2 && System.currentTimeMillis() < deadline) {
                ws.runPending(); // the event's thread queues its operation when it gets the artifact
                Thread.sleep(10);
            }
            obs.expect("panel !ok");
        }
    }

    /** Links to an operation it does not have. */
    public static class Misnamed extends GUIArtifact {
        @Override
        public void setup() {
            linkActionEventToOp(new JButton("ok"), "nowhere");
        }
    }

    /** Links a key that is not one. */
    public static class BadKey extends GUIArtifact {
        @Override
        public void setup() {
            linkKeyStrokeToOp(new JTextField(), "ENTRE", "typed");
        }

        @INTERNAL_OPERATION
        void typed(ActionEvent e) {
        }
    }

    @Test
    void aLinkToAMissingOperationOrKeyFailsTheArtifactsStartInOneLine() throws Exception {
        try (Fixture f = new Fixture()) {
            var missing = Calls.failure(f.ws, f.agent, OpTarget.any(), "makeArtifact", "m", Misnamed.class.getName(),
                    new Object[0], new OpFeedbackParam<>());
            assertEquals("init of " + Misnamed.class.getName() + " failed: java.lang.IllegalArgumentException: "
                    + Misnamed.class.getName() + " has no @INTERNAL_OPERATION (or @OPERATION) nowhere(ActionEvent) or nowhere()"
                    + " for its actionPerformed events", missing.message());
            var key = Calls.failure(f.ws, f.agent, OpTarget.any(), "makeArtifact", "k", BadKey.class.getName(),
                    new Object[0], new OpFeedbackParam<>());
            assertTrue(key.message().endsWith("not a key stroke: \"ENTRE\" (e.g. \"ENTER\", \"control S\")"), key.message());
        }
    }

    @Test
    void disposingTheArtifactEndsItsEventThread() throws Exception {
        try (Fixture f = new Fixture()) {
            NumberPanel panel = f.make("panel", NumberPanel.class);
            Thread events = Thread.getAllStackTraces().keySet().stream()
                    .filter(t -> t.getName().equals("gui-events-panel")).findFirst().orElseThrow();
            ok(f.ws, f.agent, "disposeArtifact", panel.getId());
            events.join(10_000);
            assertFalse(events.isAlive());
            onEdt(panel.ok::doClick); // nothing is listening any more, and nothing fails
            f.obs.expect("panel disposed [value(0)]");
        }
    }

    /** Links a button, then fails to start. */
    public static class Unfinished extends GUIArtifact {
        @Override
        public void setup() {
            linkActionEventToOp(new JButton("ok"), "okPressed");
            throw new IllegalStateException("cannot finish");
        }

        @INTERNAL_OPERATION
        void okPressed(ActionEvent e) {
        }
    }

    @Test
    void anArtifactThatFailsToStartLeavesNoEventThread() throws Exception {
        try (Fixture f = new Fixture()) {
            var failure = Calls.failure(f.ws, f.agent, OpTarget.any(), "makeArtifact", "u", Unfinished.class.getName(),
                    new Object[0], new OpFeedbackParam<>());
            assertEquals("init of " + Unfinished.class.getName() + " failed: java.lang.IllegalStateException: cannot finish",
                    failure.message());
            for (Thread t : Thread.getAllStackTraces().keySet()) {
                if (t.getName().equals("gui-events-u")) {
                    t.join(10_000);
                    assertFalse(t.isAlive(), "the event thread of the artifact that never started still runs");
                }
            }
        }
    }

    /** Opens a window in setup, as CArtAgO's GUI artifacts do. */
    public static class Windowed extends GUIArtifact {
        JFrame frame;

        @Override
        public void setup() {
            frame = new JFrame("windowed");
            setMainFrame(frame);
            linkWindowClosingEventToOp(frame, "closing");
        }

        @INTERNAL_OPERATION
        void closing(WindowEvent e) {
            signal("closing");
        }
    }

    @Test
    void aWindowWithoutADisplayFailsTheArtifactWithOneLine() throws Exception {
        try (Fixture f = new Fixture()) {
            OpOutcome made = Calls.call(f.ws, f.agent, OpTarget.any(), "makeArtifact", "w", Windowed.class.getName(),
                    new Object[0], new OpFeedbackParam<>());
            if (GraphicsEnvironment.isHeadless()) {
                var failure = (OpOutcome.Failure) made;
                assertEquals("init of " + Windowed.class.getName()
                        + " failed: no display for its window (DISPLAY unset, or java.awt.headless)", failure.message());
                assertFalse(failure.message().contains("\n"));
            } else {
                // with a display the window is there, and closing it is an operation
                assertTrue(made.succeeded(), made::toString);
                ArtifactId id = f.ws.lookup("w").orElseThrow();
                ok(f.ws, f.agent, "focus", id);
                f.obs.next();
                Windowed w = f.ws.artifactObject(id, Windowed.class).orElseThrow();
                onEdt(() -> w.frame.dispatchEvent(new WindowEvent(w.frame, WindowEvent.WINDOW_CLOSING)));
                f.obs.expect("w !closing");
                ok(f.ws, f.agent, "disposeArtifact", id);
                for (int i = 0; i < 100 && w.frame.isDisplayable(); i++) {
                    Thread.sleep(50);
                }
                assertFalse(w.frame.isDisplayable(), "disposing the artifact disposes its main frame");
            }
        }
    }

    @Test
    void choosingAFileWithoutADisplayFails() throws Exception {
        assumeTrue(GraphicsEnvironment.isHeadless(), "with a display the chooser would wait for a person");
        try (Fixture f = new Fixture()) {
            f.make("panel", NumberPanel.class);
            var failure = Calls.failure(f.ws, f.agent, OpTarget.any(), "selectFileToOpen", ".", "text files",
                    List.of("txt"), new OpFeedbackParam<>());
            Calls.assertReason("no_display", failure);
        }
    }
}
