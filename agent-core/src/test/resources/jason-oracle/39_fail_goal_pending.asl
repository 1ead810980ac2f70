// .fail_goal and .succeed_goal of a goal still waiting as an event (no plan chosen yet).
!start.

+!start
   <- !!g(1);                       // posted, not yet handled
      .fail_goal(g(1));
      .print(after_fail);
      !!h(2);
      .succeed_goal(h(2));
      .print(after_succeed);
      !!k(3);
      .fail_goal(k(_));
      .print(after_fail_k);
      .wait(200);
      .stopMAS.

+!g(X) <- .print(g_runs(X)).
-!g(X)[error(E)] <- .print(g_failed(X, E)).
-!g(X) <- .print(g_failed_plain(X)).
+!h(X) <- .print(h_runs(X)).
-!h(X) <- .print(h_failed(X)).
+!k(X) <- .print(k_runs(X)).
^!g(X)[state(S)] <- .print(g_state(X, S)).
^!h(X)[state(S)] <- .print(h_state(X, S)).
