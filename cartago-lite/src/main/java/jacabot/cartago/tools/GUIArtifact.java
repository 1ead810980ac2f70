package jacabot.cartago.tools;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.awt.Component;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.ItemSelectable;
import java.awt.Window;
import java.awt.event.ActionEvent;
import java.awt.event.ItemEvent;
import java.awt.event.MouseEvent;
import java.awt.event.WindowEvent;
import java.io.File;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.Arrays;
import java.util.EventObject;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JList;
import javax.swing.JSlider;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.event.ChangeEvent;
import javax.swing.event.ListSelectionEvent;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * CArtAgO's base class of artifacts with a Swing GUI. {@link #setup()} (called by {@code init})
 * builds the components and links their events to operations of the artifact with the
 * {@code link...ToOp} methods; each such event then runs the linked operation ({@link INTERNAL_OPERATION}
 * or {@link OPERATION}, taking the event or nothing), holding the artifact as any operation does.
 *
 * <p>How: the listener only queues the event, so the event dispatch thread never waits for a busy
 * artifact. A thread of the artifact takes the events in order and starts each as an internal
 * operation through an external session; the operations start in the order of their events, one
 * at a time, and one that awaits lets the next events run meanwhile, as in CArtAgO. They act for
 * no agent ({@code getCurrentOpAgentId()} is null). Disposing the artifact stops that thread and
 * disposes the {@linkplain #setMainFrame main frame}; a subclass overriding {@link #dispose()}
 * calls {@code super.dispose()}.
 */
public abstract class GUIArtifact extends Artifact {
    private static final Set<String> MOUSE_EVENTS = Set.of("mouseClicked", "mousePressed", "mouseReleased",
            "mouseEntered", "mouseExited", "mouseDragged", "mouseMoved");

    /** An operation an event kind of a source is linked to. */
    private record Target(String name, Method method) {
    }

    /** An event the listener queued for its operation. */
    private record Posted(Target target, String kind, EventObject event) {
    }

    /** An event given to its operation; {@code seq} orders the operations' starts. */
    static final class GUIEvent {
        private final long seq;
        private final Target target;
        private final String kind;
        private final EventObject event;

        private GUIEvent(long seq, Posted posted) {
            this.seq = seq;
            this.target = posted.target();
            this.kind = posted.kind();
            this.event = posted.event();
        }

        @Override
        public String toString() {
            return target.name() + " on " + kind;
        }
    }

    private final CommonEventListener listener = new CommonEventListener(this::post);
    /** Source, then event kind, to operation; written by the artifact, read on the event thread. */
    private final Map<Object, Map<String, Target>> links = new ConcurrentHashMap<>();
    private final BlockingQueue<Posted> events = new LinkedBlockingQueue<>();
    private volatile boolean stopped;
    private volatile JFrame mainFrame;
    private final Object dispatcherLock = new Object();
    private Thread dispatcher;
    /** The sequence number of the next event operation allowed to start (under the artifact's lock). */
    private long served;

    protected GUIArtifact() {
    }

    /**
     * Calls {@link #setup()}. Without a display, a window cannot be made: the artifact then fails
     * to start with the reason {@code no_display}, in one line. An artifact that fails to start is
     * never disposed, so its event thread is stopped here.
     */
    protected void init() {
        try {
            setup();
        } catch (HeadlessException e) {
            stop();
            failed("no display for its window (DISPLAY unset, or java.awt.headless)", "no_display");
        } catch (RuntimeException | Error e) {
            stop();
            throw e;
        }
    }

    /** Builds the GUI and links its events; does nothing by default. */
    public void setup() {
    }

    /** The window of the artifact: file choosers open over it; it is disposed with the artifact. */
    protected void setMainFrame(JFrame frame) {
        mainFrame = frame;
    }

    // ---- linking events to operations ----

    /** Runs {@code opName} for each action of {@code source} (a click of a button, a menu item). */
    protected void linkActionEventToOp(AbstractButton source, String opName) {
        link(source, "actionPerformed", opName, ActionEvent.class);
        if (!Arrays.asList(source.getActionListeners()).contains(listener)) {
            source.addActionListener(listener);
        }
    }

    /** Runs {@code opName} for each action of the combo box {@code source} (a choice). */
    protected void linkActionEventToOp(JComboBox<?> source, String opName) {
        link(source, "actionPerformed", opName, ActionEvent.class);
        if (!Arrays.asList(source.getActionListeners()).contains(listener)) {
            source.addActionListener(listener);
        }
    }

    /**
     * Runs {@code opName} for the mouse events of {@code source} of one type, named as the
     * listener method: {@code mouseClicked}, {@code mousePressed}, {@code mouseReleased},
     * {@code mouseEntered}, {@code mouseExited}, {@code mouseDragged} or {@code mouseMoved}.
     */
    protected void linkMouseEventToOp(Component source, String mouseEventType, String opName) {
        if (!MOUSE_EVENTS.contains(mouseEventType)) {
            throw new IllegalArgumentException("unknown mouse event type " + mouseEventType + " (one of "
                    + String.join(", ", MOUSE_EVENTS.stream().sorted().toList()) + ")");
        }
        link(source, mouseEventType, opName, MouseEvent.class);
        if (!Arrays.asList(source.getMouseListeners()).contains(listener)) {
            source.addMouseListener(listener);
        }
        if (!Arrays.asList(source.getMouseMotionListeners()).contains(listener)) {
            source.addMouseMotionListener(listener);
        }
    }

    /** Runs {@code opName} when an item of {@code source} is selected or deselected (a check box). */
    protected void linkItemEventToOp(ItemSelectable source, String opName) {
        link(source, "itemStateChanged", opName, ItemEvent.class);
        source.removeItemListener(listener); // ItemSelectable cannot list its listeners: never twice
        source.addItemListener(listener);
    }

    /** Runs {@code opName} when the selection of the list {@code source} changes. */
    protected void linkListSelectionEventToOp(JList<?> source, String opName) {
        link(source, "valueChanged", opName, ListSelectionEvent.class);
        if (!Arrays.asList(source.getListSelectionListeners()).contains(listener)) {
            source.addListSelectionListener(listener);
        }
    }

    /** Runs {@code opName} when the user asks to close the window {@code source}. */
    protected void linkWindowClosingEventToOp(Window source, String opName) {
        link(source, "windowClosing", opName, WindowEvent.class);
        if (!Arrays.asList(source.getWindowListeners()).contains(listener)) {
            source.addWindowListener(listener);
        }
    }

    /**
     * Runs {@code opName} when {@code key} is pressed while {@code source} has the focus;
     * {@code key} is written as {@link KeyStroke#getKeyStroke(String)} reads it ({@code "ENTER"},
     * {@code "control S"}). The operation receives an {@link ActionEvent}. Several keys of one
     * component may each have their operation.
     */
    protected void linkKeyStrokeToOp(JComponent source, String key, String opName) {
        KeyStroke stroke = KeyStroke.getKeyStroke(key);
        if (stroke == null) {
            throw new IllegalArgumentException("not a key stroke: \"" + key + "\" (e.g. \"ENTER\", \"control S\")");
        }
        String kind = "keyStroke " + stroke;
        link(source, kind, opName, ActionEvent.class);
        source.getInputMap().put(stroke, kind);
        source.getActionMap().put(kind, listener.action(kind));
    }

    /** Runs {@code opName} when the value of the slider {@code source} changes. */
    protected void linkChangeEventToOp(JSlider source, String opName) {
        link(source, "stateChanged", opName, ChangeEvent.class);
        if (!Arrays.asList(source.getChangeListeners()).contains(listener)) {
            source.addChangeListener(listener);
        }
    }

    /**
     * Links the events of {@code source} that reach {@link #getEventListenerInstance()} through
     * its method {@code type} (e.g. {@code "actionPerformed"}) to {@code opName}: for sources the
     * {@code link...ToOp} methods do not cover, to which the caller adds that listener.
     */
    protected void insertEventToOp(Object source, String type, String opName) {
        link(source, type, opName, null);
    }

    /** {@return the listener that hands Swing events to this artifact} */
    protected CommonEventListener getEventListenerInstance() {
        return listener;
    }

    private void link(Object source, String kind, String opName, Class<?> eventType) {
        if (source == null || opName == null) {
            throw new IllegalArgumentException("linking " + kind + " events: null " + (source == null ? "source" : "operation"));
        }
        links.computeIfAbsent(source, s -> new ConcurrentHashMap<>()).put(kind, target(opName, kind, eventType));
        startDispatcher();
    }

    /**
     * {@return the operation called {@code opName} that takes one event of {@code eventType}
     * (any type when null) or nothing}, most derived class first
     */
    private Target target(String opName, String kind, Class<?> eventType) {
        Method noParameter = null;
        for (Class<?> c = getClass(); c != null && c != Artifact.class; c = c.getSuperclass()) {
            for (Method m : c.getDeclaredMethods()) {
                boolean operation = m.isAnnotationPresent(INTERNAL_OPERATION.class) || m.isAnnotationPresent(OPERATION.class);
                if (!operation || !m.getName().equals(opName)) {
                    continue;
                }
                if (m.getParameterCount() == 1 && (eventType == null || m.getParameterTypes()[0].isAssignableFrom(eventType))) {
                    m.setAccessible(true);
                    return new Target(opName, m);
                }
                if (m.getParameterCount() == 0 && noParameter == null) {
                    noParameter = m;
                }
            }
        }
        if (noParameter == null) {
            String event = eventType == null ? "an event" : eventType.getSimpleName();
            throw new IllegalArgumentException(getClass().getName() + " has no @INTERNAL_OPERATION (or @OPERATION) "
                    + opName + "(" + event + ") or " + opName + "() for its " + kind + " events");
        }
        noParameter.setAccessible(true);
        return new Target(opName, noParameter);
    }

    // ---- from the event dispatch thread to operations ----

    /** Called by the listener (on the event dispatch thread): queues the event if it is linked. */
    private void post(String kind, EventObject event) {
        Map<String, Target> kinds = links.get(event.getSource());
        Target target = kinds == null ? null : kinds.get(kind);
        if (target != null && !stopped) {
            events.add(new Posted(target, kind, event));
        }
    }

    private void startDispatcher() {
        synchronized (dispatcherLock) {
            if (dispatcher == null && !stopped) {
                dispatcher = new Thread(this::dispatch, "gui-events-" + getId().getName());
                dispatcher.setDaemon(true);
                dispatcher.start();
            }
        }
    }

    /** The artifact's thread: starts one operation per event, numbered in arrival order. */
    private void dispatch() {
        long next = 0;
        try {
            while (!stopped) {
                Posted posted = events.take();
                beginExternalSession();
                boolean ok = false;
                try {
                    if (!stopped) {
                        execInternalOp("handleGUIEvent", new GUIEvent(next++, posted));
                    }
                    ok = true;
                } finally {
                    endExternalSession(ok);
                }
            }
        } catch (InterruptedException disposed) {
            // the artifact is disposed: no more events
        } catch (RuntimeException closed) {
            // the workspace refuses new operations: it is closing
        }
    }

    /** The event's turn has come: the operations of earlier events have started. */
    @GUARD
    boolean inTurn(GUIEvent e) {
        return e.seq == served;
    }

    /** Runs the operation linked to an event, after its own guard if it has one. */
    @INTERNAL_OPERATION(guard = "inTurn")
    void handleGUIEvent(GUIEvent e) {
        served++;
        Method op = e.target.method();
        Object[] args = op.getParameterCount() == 0 ? new Object[0] : new Object[] {e.event};
        if (args.length == 1 && !op.getParameterTypes()[0].isInstance(e.event)) {
            failed(getClass().getName() + "." + e.target.name() + " takes " + op.getParameterTypes()[0].getSimpleName()
                    + ", not the " + e.event.getClass().getSimpleName() + " of its " + e.kind + " events", "bad_event",
                    e.target.name(), e.kind);
        }
        String guard = guardOf(op);
        if (!guard.isEmpty()) {
            await(guard, args);
        }
        try {
            op.invoke(this, args);
        } catch (InvocationTargetException x) {
            Throwable cause = x.getCause();
            if (cause instanceof RuntimeException r) {
                throw r;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(e.target.name() + " threw " + cause, cause);
        } catch (IllegalAccessException x) {
            throw new IllegalStateException(x);
        }
    }

    private static String guardOf(Method op) {
        INTERNAL_OPERATION internal = op.getAnnotation(INTERNAL_OPERATION.class);
        return internal != null ? internal.guard() : op.getAnnotation(OPERATION.class).guard();
    }

    // ---- operations ----

    /**
     * Lets the user choose a file to open, in {@code currentDir}, among those with one of
     * {@code extensions} (described as {@code fileDesc}); the artifact is free meanwhile. Fails
     * with {@code no_file_selected} when the user cancels, {@code no_display} without a display.
     */
    @OPERATION
    void selectFileToOpen(String currentDir, String fileDesc, String[] extensions, OpFeedbackParam<String> selectedFile) {
        if (GraphicsEnvironment.isHeadless()) {
            failed("selectFileToOpen needs a display", "no_display");
        }
        JFrame owner = mainFrame;
        String[] chosen = new String[1];
        await(() -> {
            try {
                SwingUtilities.invokeAndWait(() -> {
                    JFileChooser chooser = new JFileChooser(new File(currentDir));
                    chooser.setFileFilter(new FileNameExtensionFilter(fileDesc, extensions));
                    if (chooser.showOpenDialog(owner) == JFileChooser.APPROVE_OPTION) {
                        chosen[0] = chooser.getSelectedFile().getAbsolutePath();
                    }
                });
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while the file chooser was open");
            } catch (InvocationTargetException e) {
                throw e.getCause() instanceof RuntimeException r ? r : new IllegalStateException(e.getCause());
            }
        });
        if (chosen[0] == null) {
            failed("no_file_selected", "no_file_selected");
        }
        selectedFile.set(chosen[0]);
    }

    /** Stops turning events into operations and disposes the main frame. */
    @Override
    protected void dispose() {
        stop();
    }

    private void stop() {
        stopped = true;
        events.clear();
        synchronized (dispatcherLock) {
            if (dispatcher != null) {
                dispatcher.interrupt();
            }
        }
        JFrame frame = mainFrame;
        if (frame != null) {
            SwingUtilities.invokeLater(frame::dispose);
        }
    }
}
