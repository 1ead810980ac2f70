package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.INTERNAL_OPERATION;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import java.util.ArrayList;
import java.util.List;

/** Takes offers until its time is up, then gives them to the announcer, who names a winner. */
public class Auction extends Artifact {
    /** An offer; agents hold it as a Java object and hand it back to award. */
    public record Offer(int id, String text) {
        @Override
        public String toString() {
            return text;
        }
    }

    private final List<Offer> offers = new ArrayList<>();

    void init(String description, int millis) {
        defineObsProperty("state", "open");
        execInternalOp("closeAfter", millis);
    }

    @INTERNAL_OPERATION
    void closeAfter(int millis) {
        await_time(millis);
        getObsProperty("state").updateValue("closed");
    }

    @OPERATION
    void offer(String text, OpFeedbackParam<Integer> id) {
        if (!getObsProperty("state").stringValue().equals("open")) {
            failed("the auction is closed", "auction_closed");
        }
        Offer o = new Offer(offers.size() + 1, text);
        offers.add(o);
        id.set(o.id());
    }

    @OPERATION
    void offers(OpFeedbackParam<Offer[]> all) {
        await("closed");
        all.set(offers.toArray(new Offer[0]));
    }

    @GUARD
    boolean closed() {
        return getObsProperty("state").stringValue().equals("closed");
    }

    @OPERATION
    void award(Offer winner) {
        defineObsProperty("winner", winner.id());
    }
}
