package demo;

import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;
import jacabot.cartago.tools.GUIArtifact;
import java.awt.BorderLayout;
import java.awt.event.ActionEvent;
import java.awt.event.MouseEvent;
import java.awt.event.WindowEvent;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

/** A window with a number: its property {@code value}, set by ENTER in the field or by agents. */
public class NumberWindow extends GUIArtifact {
    private JFrame frame;
    private JTextField number;

    @Override
    public void setup() {
        frame = new JFrame("jacabot: 07a GUI");
        frame.setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE); // the agent decides
        number = new JTextField("0", 8);
        number.setName("number");
        JButton ok = new JButton("ok");
        ok.setName("ok");
        JPanel row = new JPanel();
        row.add(number);
        row.add(ok);
        JPanel pad = new JPanel();
        pad.setName("pad");
        pad.add(new JLabel("drag the mouse here"));
        frame.getContentPane().add(row, BorderLayout.NORTH);
        frame.getContentPane().add(pad, BorderLayout.CENTER);
        frame.setSize(320, 160);

        defineObsProperty("value", 0);
        linkActionEventToOp(ok, "okPressed");
        linkKeyStrokeToOp(number, "ENTER", "numberEntered");
        linkMouseEventToOp(pad, "mouseDragged", "dragged");
        linkWindowClosingEventToOp(frame, "closing");
        setMainFrame(frame);
        frame.setVisible(true);
    }

    @INTERNAL_OPERATION
    void okPressed(ActionEvent e) {
        signal("ok");
    }

    @INTERNAL_OPERATION
    void numberEntered(ActionEvent e) {
        String text = number.getText().trim();
        try {
            getObsProperty("value").updateValue(Integer.parseInt(text));
        } catch (NumberFormatException notANumber) {
            failed("not a whole number: " + text);
        }
    }

    @INTERNAL_OPERATION
    void dragged(MouseEvent e) {
        signal("dragged", e.getX(), e.getY());
    }

    @INTERNAL_OPERATION
    void closing(WindowEvent e) {
        signal("closed");
    }

    @OPERATION
    void setValue(int value) {
        getObsProperty("value").updateValue(value);
        SwingUtilities.invokeLater(() -> number.setText(String.valueOf(value)));
    }
}
