// 200 intentions started with !! that run 300 subgoals each, in round robin.
!go.
+!go <- .print(start); for (.range(I, 1, 200)) { !!work(I, 0) }.
+!work(I, 300) <- +done(I); .count(done(_), C); if (C == 200) { .print(end); .stopMAS }.
+!work(I, N) <- !work(I, N + 1).
