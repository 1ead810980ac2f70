// Ping-pong between two agents: 10 000 tells, each answered (waking the other agent each time).
!start.
+!start <- .print(start); .send(pong, tell, ball(0)).
+ball(N)[source(pong)] : N >= 10000 <- .print(end); .stopMAS.
+ball(N)[source(pong)] <- -ball(N)[source(pong)]; .send(pong, tell, ball(N + 1)).
