package jacabot.cartago.examples;

import jacabot.cartago.Artifact;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;

/** CArtAgO's clock: an internal operation loops with await_time and signals ticks. */
public class Clock extends Artifact {
    private boolean working;
    private long period;

    void init(long period) {
        this.period = period;
        defineObsProperty("ticks", 0);
    }

    @OPERATION
    void start() {
        if (working) {
            failed("already working");
        }
        working = true;
        execInternalOp("work");
    }

    @OPERATION
    void stop() {
        working = false;
    }

    @INTERNAL_OPERATION
    void work() {
        while (true) {
            await_time(period);
            if (!working) {
                return;
            }
            int ticks = getObsProperty("ticks").intValue() + 1;
            getObsProperty("ticks").updateValue(ticks);
            signal("tick", ticks);
        }
    }
}
