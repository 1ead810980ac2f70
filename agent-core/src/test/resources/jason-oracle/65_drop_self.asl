// .drop_intention without argument drops the running intention.
!a. !b.
+!a <- .print(a1); .drop_intention; .print(never).
+!b <- .print(b1); .print(b2); .print(b3); .stopMAS.
