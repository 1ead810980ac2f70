!allocate("t0", 1000).
+!allocate(Task, Millis)
    <- makeArtifact("task_board", "demo.TaskBoard", []);
       announce(Task, Millis, Auction);
       println("announced ", Task, " on ", Auction);
       offers(Offers) [artifact_name(Auction)];
       .length(Offers, N);
       println("got ", N, " offers");
       Offers = [Best | _];
       award(Best) [artifact_name(Auction)];
       println("awarded to ", Best);
       withdraw(Auction).
// every bidder reports when it is done (late, won or lost)
+done[source(B)] <- .count(done[source(_)], N); !finish(N).
+!finish(5) <- println("all bidders done"); .stopMAS.
+!finish(_).
