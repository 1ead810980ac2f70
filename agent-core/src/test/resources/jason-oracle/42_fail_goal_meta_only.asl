// .fail_goal of a goal still waiting as an event, with a goal-state plan (^!g) and no -!g plan.
!start.
+!start <- !!g(1); .fail_goal(g(_)); .wait(50); .print(after); !!h(2); .succeed_goal(h(_)); .wait(50); .print(end); .stopMAS.
+!g(X) <- .print(g(X)).
+!h(X) <- .print(h(X)).
^!g(X)[state(S)] <- .print(state(X, S)).
^!h(X)[state(S)] <- .print(hstate(X, S)).
