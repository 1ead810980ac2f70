// Several intentions waiting on the same event resume in order; !! intentions run interleaved.
!w1. !w2. !trigger.
+!w1 <- .wait({+go}); .print(w1).
+!w2 <- .wait({+go}); .print(w2).
+!trigger <- .print(t1); .print(t2); +go; .print(t3); .print(t4); .print(t5); .stopMAS.
