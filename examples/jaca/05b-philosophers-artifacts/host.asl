!lay_table.
+!lay_table
    <- makeArtifact("tickets", "demo.Tickets", [4]);
       for (.range(I, 0, 4)) { .concat("fork", I, F); makeArtifact(F, "demo.Fork", []) };
       for (.range(I, 1, 5)) { .concat("philosopher", I, P); .send(P, tell, forks(I - 1, I mod 5)) }.
+full[source(P)] <- println(P, " is full"); .count(full[source(_)], N); !maybe_end(N).
+!maybe_end(5) <- println("all philosophers ate"); .stopMAS.
+!maybe_end(_).
