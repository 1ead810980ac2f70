// Three intentions created in the same cycle order, with subgoals.
!a. !b. !c.
+!a <- .print(a1); !sub(a); .print(a2).
+!b <- .print(b1); !sub(b); .print(b2).
+!c <- .print(c1); .print(c2); .print(c3); .print(c4); .print(c5); .print(c6); .stopMAS.
+!sub(X) <- .print(sub, X).
