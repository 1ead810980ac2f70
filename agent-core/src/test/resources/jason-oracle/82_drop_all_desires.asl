!g.
@g[atomic] +!g <- !!a; !!b; +c; .drop_all_desires; .print(dropped); !!after.
+!after <- .wait(50); .print(end); .stopMAS.
+!a <- .print(a).
+!b <- .print(b).
+c <- .print(c).
