package demo;

import jacabot.cartago.Artifact;
import jacabot.cartago.ArtifactConfig;
import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;

/** Publishes tasks as task(Description, AuctionName) properties, one auction artifact per task. */
public class TaskBoard extends Artifact {
    private int auctions;

    @OPERATION
    void announce(String description, int millis, OpFeedbackParam<String> auction) {
        String name = "auction_" + (++auctions);
        makeArtifact(name, "demo.Auction", new ArtifactConfig(description, millis));
        defineObsProperty("task", description, name);   // several tasks may be open at once
        auction.set(name);
    }

    @OPERATION
    void withdraw(String auction) {
        removeObsPropertyByTemplate("task", null, auction);
    }
}
