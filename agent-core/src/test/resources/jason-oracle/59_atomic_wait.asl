// An atomic plan that waits lets nothing else run... until the wait ends.
!a. !b.
@x[atomic] +!a <- .print(a1); .wait(20); .print(a2).
+!b <- .print(b1); .print(b2); .print(b3); .wait(60); .stopMAS.
