!g.
@g[atomic] +!g <- !!a; +c; .drop_all_events; .print(dropped); !!after.
+!after <- .wait(50); .print(end); .stopMAS.
+!a <- .print(a).
+c <- .print(c).
