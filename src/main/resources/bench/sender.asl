// 20 000 tell messages to the receiver.
!bench.
+!bench <- .print(start); !send(0).
+!send(20000) <- .send(receiver, tell, last).
+!send(N) <- .send(receiver, tell, n(N)); !send(N + 1).
