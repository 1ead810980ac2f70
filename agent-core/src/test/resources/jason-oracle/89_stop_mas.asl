!g. !h.
+!g <- .print(before); .stopMAS; .print(after).
+!h <- .wait(200); .print(late).
