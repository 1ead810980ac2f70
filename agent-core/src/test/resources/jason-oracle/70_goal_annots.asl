// Goals carry source annotations; plans can select on them; the failure plan sees them too.
!start.
+!start <- !g(1); !g(2)[urgent]; .print(done); .stopMAS.
+!g(X)[urgent] <- .print("urgent ", X).
+!g(X)[source(S)] <- .print("normal ", X, " from ", S).
