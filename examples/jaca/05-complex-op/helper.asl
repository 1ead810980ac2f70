+ready[source(starter)] <- !give(4).
+!give(N) : N > 0 <- contribute(3); println("contributed"); !give(N - 1).
+!give(0) <- .send(starter, tell, finished).
