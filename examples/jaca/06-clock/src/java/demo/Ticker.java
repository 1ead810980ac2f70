package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;

/** Signals tick every period milliseconds between start and stop. */
public class Ticker extends Artifact {
    private long period;
    private boolean running;

    void init(int period) {
        this.period = period;
    }

    @OPERATION
    void start() {
        if (running) {
            failed("already ticking", "already_running");
        }
        running = true;
        execInternalOp("tickLoop");
    }

    @OPERATION
    void stop() {
        running = false;
    }

    @INTERNAL_OPERATION
    void tickLoop() {
        while (running) {
            signal("tick");
            await_time(period);
        }
    }
}
