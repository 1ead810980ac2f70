// Initial beliefs and goals: their events are handled in order, beliefs first.
b(1). b(2).
!g1. !g2.
+b(X) <- .print("+b ", X).
+!g1 <- .print(g1).
+!g2 <- .print(g2); .stopMAS.
