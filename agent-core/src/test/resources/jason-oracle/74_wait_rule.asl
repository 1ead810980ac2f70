// .wait on a formula with a rule; the waiting intention resumes when it becomes true.
limit(3).
reached :- c(N) & limit(L) & N >= L.
c(0).
!watch. !count.
+!watch <- .wait(reached); ?c(N); .print("reached ", N); .stopMAS.
+!count <- for (.range(I, 1, 5)) { -+c(I); .print("c=", I) }.
