// 200 000 additions and deletions of a belief in a for loop.
!bench.
+!bench <- .print(start); for (.range(I, 1, 200000)) { +v(I); -v(I) }; .print(end); .stopMAS.
