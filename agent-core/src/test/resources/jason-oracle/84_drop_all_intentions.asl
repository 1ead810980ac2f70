!g. !h.
+!g <- .print(g1); .wait(20); .print(g2).
+!h <- .print(h1); .drop_all_intentions; .print(h2); .wait(100); .stopMAS.
