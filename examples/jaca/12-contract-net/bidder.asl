!find_work("t0", 1400).
+!find_work(Task, MaxThinking) <- +wanted(Task); +thinking(MaxThinking); focusWhenAvailable("task_board").
+task(Task, Auction) : wanted(Task)
    <- lookupArtifact(Auction, Id); focus(Id); !offer(Task, Id).
+!offer(Task, Id)
    <- ?thinking(Max); .wait(math.random(Max));
       .my_name(Me); .concat("offer_of_", Me, Text);
       offer(Text, OfferId) [artifact_id(Id)];
       +my_offer(OfferId);
       println("offer ", OfferId, " made").
-!offer(Task, Id) <- println("too late for an offer"); .send(announcer, tell, done).
+winner(W) : my_offer(W) <- println("I won"); .send(announcer, tell, done).
+winner(W) : my_offer(_) <- println("I lost"); .send(announcer, tell, done).
