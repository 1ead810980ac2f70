// each producer puts 10 items; producer1 ends the run when 20 were consumed
!produce.
+!produce <- !queue(Q); for (.range(I, 1, 10)) { .my_name(Me); put(item(Me, I)) }.
+!queue(Q) <- makeArtifact("queue", "demo.Queue", [3], Q); focus(Q).
-!queue(Q) <- lookupArtifact("queue", Q); focus(Q).
+consumed(20) : .my_name(producer1) <- .stopMAS.
