// Waits for the 1 000 workers to count to 1 000 each.
done(0).
!bench.
+!bench <- .print(start).
+finished[source(A)] : done(N) <- -+done(N + 1); !check.
+!check : done(1000) <- .print(end); .stopMAS.
+!check.
