// .fail_goal of a sub-goal still waiting as an event of the intention that posted it.
!a.
!b.

+!a <- !g(1); .print(a_after); .wait(200); .stopMAS.
+!b <- .fail_goal(g(1)); .print(b_after).
+!g(X) <- .print(g_runs(X)).
-!g(X)[error(E)] <- .print(g_failed(X, E)).
-!g(X) <- .print(g_failed_plain(X)).
^!g(X)[state(S)] <- .print(g_state(X, S)).
