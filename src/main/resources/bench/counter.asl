// A while loop of 200 000 -+counter(N) updates.
counter(0).
!bench.
+!bench <- .print(start); while (counter(N) & N < 200000) { -+counter(N + 1) }; .print(end); .stopMAS.
