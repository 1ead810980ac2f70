package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Component;
import java.awt.Container;
import java.awt.Frame;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.concurrent.Future;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.text.JTextComponent;
import org.opentest4j.AssertionFailedError;

/** Works a shown window through the system's input events (java.awt.Robot); needs a display. */
final class SwingDriver {
    private final Robot robot;

    SwingDriver() throws Exception {
        robot = new Robot();
        robot.setAutoDelay(30);
    }

    /** {@return the shown frame titled {@code title}, waiting up to 30 s while {@code run} goes on} */
    static JFrame frame(String title, Future<?> run) throws Exception {
        long deadline = System.currentTimeMillis() + 30_000;
        while (System.currentTimeMillis() < deadline && !run.isDone()) {
            for (Frame f : Frame.getFrames()) {
                if (f instanceof JFrame j && title.equals(f.getTitle()) && f.isShowing()) {
                    return j;
                }
            }
            Thread.sleep(50);
        }
        if (run.isDone()) {
            fail("the run ended before its window showed: " + run.get());
        }
        return fail("no window \"" + title + "\" within 30 s");
    }

    /** {@return the component of {@code type} named {@code name} in {@code root}} */
    static <T extends Component> T find(Container root, Class<T> type, String name) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && name.equals(c.getName())) {
                return type.cast(c);
            }
            if (c instanceof Container inner) {
                T found = findOrNull(inner, type, name);
                if (found != null) {
                    return found;
                }
            }
        }
        return fail("no " + type.getSimpleName() + " named " + name);
    }

    private static <T extends Component> T findOrNull(Container root, Class<T> type, String name) {
        try {
            return find(root, type, name);
        } catch (AssertionFailedError notHere) {
            return null;
        }
    }

    private Point centre(Component c) throws Exception {
        Point[] p = new Point[1];
        SwingUtilities.invokeAndWait(() -> {
            Point at = c.getLocationOnScreen();
            p[0] = new Point(at.x + c.getWidth() / 2, at.y + c.getHeight() / 2);
        });
        return p[0];
    }

    void click(Component c) throws Exception {
        Point p = centre(c);
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    /** Selects the field's text, types {@code digits} and ENTER. */
    void type(JTextComponent field, String digits) throws Exception {
        SwingUtilities.invokeAndWait(field::selectAll);
        for (char d : digits.toCharArray()) {
            int key = KeyEvent.VK_0 + (d - '0');
            robot.keyPress(key);
            robot.keyRelease(key);
        }
        robot.keyPress(KeyEvent.VK_ENTER);
        robot.keyRelease(KeyEvent.VK_ENTER);
        robot.waitForIdle();
    }

    /** Drags across {@code c} with the first button held. */
    void drag(Component c) throws Exception {
        Point p = centre(c);
        robot.mouseMove(p.x - 20, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int dx = -15; dx <= 20; dx += 5) {
            robot.mouseMove(p.x + dx, p.y + dx / 5);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    /** Waits up to 20 s for {@code field} to show {@code text}. */
    void waitForText(JTextComponent field, String text) throws Exception {
        long deadline = System.currentTimeMillis() + 20_000;
        while (!text.equals(field.getText())) {
            if (System.currentTimeMillis() > deadline) {
                fail("the field shows \"" + field.getText() + "\", not \"" + text + "\"");
            }
            Thread.sleep(20);
        }
    }
}
