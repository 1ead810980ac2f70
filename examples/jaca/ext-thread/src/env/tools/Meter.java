package tools;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;

/** A reading that a background thread raises every period; agents may also bump it. */
public class Meter extends Artifact {
    private Thread feeder;

    void init(int start, int period) {
        defineObsProperty("reading", start);
        feeder = new Thread(() -> {
            try {
                while (true) {
                    Thread.sleep(period);
                    raiseFromOutside();
                }
            } catch (InterruptedException e) {
                // disposed: stop feeding
            }
        }, "meter-feeder");
        feeder.setDaemon(true);
        feeder.start();
    }

    private void raiseFromOutside() {
        beginExternalSession();
        boolean ok = false;
        try {
            getObsProperty("reading").updateValue(getObsProperty("reading").intValue() + 1);
            ok = true;
        } finally {
            endExternalSession(ok);
        }
    }

    @OPERATION
    void bump() {
        getObsProperty("reading").updateValue(getObsProperty("reading").intValue() + 100);
    }

    @Override
    protected void dispose() {
        feeder.interrupt();
    }
}
