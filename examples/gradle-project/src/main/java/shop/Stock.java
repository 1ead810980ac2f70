package shop;

import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;

/** A shop's stock of one product: sell fails when it is empty. */
public class Stock extends Artifact {
    void init(int items) {
        defineObsProperty("items", items);
    }

    @OPERATION
    void sell() {
        int left = getObsProperty("items").intValue();
        if (left == 0) {
            failed("sold out", "sold_out");
        }
        getObsProperty("items").updateValue(left - 1);
    }
}
