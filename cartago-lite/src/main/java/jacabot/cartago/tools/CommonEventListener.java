package jacabot.cartago.tools;

import java.awt.event.ActionEvent;
import java.awt.event.ActionListener;
import java.awt.event.ItemEvent;
import java.awt.event.ItemListener;
import java.awt.event.MouseEvent;
import java.awt.event.MouseListener;
import java.awt.event.MouseMotionListener;
import java.awt.event.WindowEvent;
import java.awt.event.WindowListener;
import java.util.EventObject;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.event.ChangeEvent;
import javax.swing.event.ChangeListener;
import javax.swing.event.ListSelectionEvent;
import javax.swing.event.ListSelectionListener;

/**
 * The one Swing listener of a {@link GUIArtifact}, as in CArtAgO: it is added to every linked
 * component and hands each event on, with the name of the listener method that received it
 * ({@code actionPerformed}, {@code mouseDragged}, {@code windowClosing}, ...), to the artifact,
 * which turns it into an operation. It runs on the event dispatch thread and never waits for the
 * artifact, so a busy artifact does not freeze the GUI.
 */
public final class CommonEventListener implements ActionListener, ItemListener, ListSelectionListener, WindowListener,
        MouseListener, MouseMotionListener, ChangeListener {
    /** Receives each event with the name of the listener method it arrived through. */
    interface Sink {
        void post(String kind, EventObject event);
    }

    private final Sink sink;

    CommonEventListener(Sink sink) {
        this.sink = sink;
    }

    /**
     * {@return a Swing action that hands its events on as {@code kind}}: key strokes reach an
     * artifact through a component's input and action maps, not through a listener.
     */
    Action action(String kind) {
        return new AbstractAction(kind) {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                sink.post(kind, e);
            }
        };
    }

    @Override
    public void actionPerformed(ActionEvent e) {
        sink.post("actionPerformed", e);
    }

    @Override
    public void itemStateChanged(ItemEvent e) {
        sink.post("itemStateChanged", e);
    }

    @Override
    public void valueChanged(ListSelectionEvent e) {
        sink.post("valueChanged", e);
    }

    @Override
    public void stateChanged(ChangeEvent e) {
        sink.post("stateChanged", e);
    }

    @Override
    public void windowClosing(WindowEvent e) {
        sink.post("windowClosing", e);
    }

    @Override
    public void windowOpened(WindowEvent e) {
        sink.post("windowOpened", e);
    }

    @Override
    public void windowClosed(WindowEvent e) {
        sink.post("windowClosed", e);
    }

    @Override
    public void windowIconified(WindowEvent e) {
        sink.post("windowIconified", e);
    }

    @Override
    public void windowDeiconified(WindowEvent e) {
        sink.post("windowDeiconified", e);
    }

    @Override
    public void windowActivated(WindowEvent e) {
        sink.post("windowActivated", e);
    }

    @Override
    public void windowDeactivated(WindowEvent e) {
        sink.post("windowDeactivated", e);
    }

    @Override
    public void mouseClicked(MouseEvent e) {
        sink.post("mouseClicked", e);
    }

    @Override
    public void mousePressed(MouseEvent e) {
        sink.post("mousePressed", e);
    }

    @Override
    public void mouseReleased(MouseEvent e) {
        sink.post("mouseReleased", e);
    }

    @Override
    public void mouseEntered(MouseEvent e) {
        sink.post("mouseEntered", e);
    }

    @Override
    public void mouseExited(MouseEvent e) {
        sink.post("mouseExited", e);
    }

    @Override
    public void mouseDragged(MouseEvent e) {
        sink.post("mouseDragged", e);
    }

    @Override
    public void mouseMoved(MouseEvent e) {
        sink.post("mouseMoved", e);
    }
}
