package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;

/** At most n philosophers try to eat at once. */
public class Tickets extends Artifact {
    private int left;

    void init(int n) {
        left = n;
    }

    @OPERATION(guard = "available")
    void acquireTicket() {
        left--;
    }

    @OPERATION
    void returnTicket() {
        left++;
    }

    @GUARD
    boolean available() {
        return left > 0;
    }
}
