!lay_table.
+!lay_table
    <- makeArtifact("tickets", "demo.Tickets", [4]);
       for (.range(I, 0, 4)) { .concat("fork", I, F); makeArtifact(F, "demo.Fork", []) };
       for (.range(I, 1, 5)) { .concat("philosopher", I, P); .send(P, tell, forks(I - 1, I mod 5)) }.
// count the full philosophers as their messages are handled (atomic: one at a time); counting the
// belief's sources saw a tell whose event was still queued, and .stopMAS cut that line
eaten(0).
@full[atomic]
+full[source(P)] : eaten(N) <- println(P, " is full"); -+eaten(N + 1); !maybe_end(N + 1).
+!maybe_end(5) <- println("all philosophers ate"); .stopMAS.
+!maybe_end(_).
