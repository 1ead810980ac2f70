done(0).
+finished[source(A)] : done(N) <- -+done(N + 1); !check.
+!check : done(1000) <- .stopMAS.
+!check.
