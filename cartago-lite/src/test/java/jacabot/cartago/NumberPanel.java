package jacabot.cartago;

import jacabot.cartago.tools.GUIArtifact;
import java.awt.event.ActionEvent;
import java.awt.event.MouseEvent;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.swing.JButton;
import javax.swing.JPanel;

/**
 * A number in a text field with an ok button and a pad to drag on, without a window (so that it
 * can be made without a display): ok signals {@code ok}, ENTER in the field makes the field's
 * number the property {@code value}, a drag on the pad signals {@code dragged(X, Y)}.
 */
public class NumberPanel extends GUIArtifact {
    public final KeyField field = new KeyField("0", 6);
    public final JButton ok = new JButton("ok");
    public final JPanel pad = new JPanel();
    /** Counted down when {@link #hold()} holds the artifact; {@link #release} ends it. */
    public final CountDownLatch holding = new CountDownLatch(1);
    public final CountDownLatch release = new CountDownLatch(1);

    @Override
    public void setup() {
        defineObsProperty("value", 0);
        linkActionEventToOp(ok, "okPressed");
        linkKeyStrokeToOp(field, "ENTER", "numberEntered");
        linkMouseEventToOp(pad, "mouseDragged", "dragged");
    }

    @INTERNAL_OPERATION
    void okPressed(ActionEvent e) {
        signal("ok");
    }

    @INTERNAL_OPERATION
    void numberEntered(ActionEvent e) {
        getObsProperty("value").updateValue(Integer.parseInt(field.getText().trim()));
    }

    @INTERNAL_OPERATION
    void dragged(MouseEvent e) {
        signal("dragged", e.getX(), e.getY());
    }

    @OPERATION
    void setValue(int value) {
        field.setText(String.valueOf(value));
        getObsProperty("value").updateValue(value);
    }

    /** Holds the artifact (no await) until the test releases it. */
    @OPERATION
    void hold() throws InterruptedException {
        holding.countDown();
        if (!release.await(20, TimeUnit.SECONDS)) {
            failed("never released");
        }
    }
}
