b(1)[source(ag1)]. c(2)[source(ag2)]. d[source(ag2), x].
!g.
+!g <- .count(_[source(ag2)], N); .print(N);
       .findall(V, V[x] = d[source(ag2), x], L); .print(L);
       .abolish(_[source(ag2)]); .count(_[source(ag2)], M); .print(M);
       !fails.
+!fails <- .fail(reason(1)).
-!fails[error(E), reason(R)] <- .print(R); .stopMAS.
