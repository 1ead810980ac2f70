package jacabot.cartago;

import java.awt.event.KeyEvent;
import javax.swing.JTextField;

/**
 * A text field that takes key presses without having the focus: without a display no component
 * is showing, and the focus manager drops key events of components that are not, so tests hand
 * the event to the component's own key processing (its key listeners, then its key bindings),
 * which is where the focus manager would deliver it.
 */
public class KeyField extends JTextField {
    private static final long serialVersionUID = 1L;

    public KeyField(String text, int columns) {
        super(text, columns);
    }

    /** Types {@code text} and presses ENTER; call on the event dispatch thread. */
    public void enter(String text) {
        setText(text);
        processKeyEvent(new KeyEvent(this, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0, KeyEvent.VK_ENTER, '\n'));
    }
}
