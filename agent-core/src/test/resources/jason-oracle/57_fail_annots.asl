// .fail with annotations; error annotations in the failure event.
!start.
+!start <- !g; .print(after); .stopMAS.
+!g <- .fail(error(custom), reason(42)).
-!g[error(E), reason(R)] <- .print(E, " ", R).
