// 30 000 turns of annotated beliefs: add, test and remove by annotation, .abolish.
!go.
+!go <- .print(start); !a(0).
+!a(30000) <- .print(end); .stopMAS.
+!a(N) <- +seen(N mod 50)[t(N), src(x)]; ?seen(N mod 50)[t(T)]; -seen(N mod 50)[t(T)]; .abolish(seen(_)); !a(N + 1).
