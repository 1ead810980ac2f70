!g.
@g[atomic] +!g <- !!b(1); !!b(2); .drop_event(b(1)); .print(dropped); !!after.
+!after <- .wait(50); .stopMAS.
+!b(X) <- .print(b, X).
