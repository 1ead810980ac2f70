// Jason's goal patterns { begin P } ... { end }: dg adds +!G : G, +!G : .intend(G), ?G at the end
// of the block's plans for G and +G <- .succeed_goal(G); bdg adds -!G <- !G; bc adds +!G <- !G;
// smc(G, F) adds +F <- .fail_goal(G). The generated plans come from no file.
c(0).
!start.
+!start <- !done; .print(done_finished);
           !j; .print(j_finished);
           !g; .print(g_finished);
           .relevant_plans({+!j}, Ps); .length(Ps, N); .print(N);
           .relevant_plans({+dc}, [P]); .print(P);
           !!k; .wait(200); +stop; .wait(200);
           .stopMAS.
-!start[error(E)] <- .print(start_failed(E)).

{ begin bc(done) }
+!done : c(N) & N < 3 <- -+c(N + 1); .print(c(N + 1)).
+!done : c(3) <- +done.
{ end }

{ begin smc(j, dc) }
+!j : bel <- .print(a).
+!j <- .print(b).
{ end }

{ begin dg(g) }
+!g <- .print(trying_g); +g.
{ end }

{ begin smc(k, stop) }
+!k <- .print(k); .wait(100).
{ end }
-!k[error(E)] <- .print(k_failed(E)).
