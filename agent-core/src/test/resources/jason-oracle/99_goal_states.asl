// Goal-state meta-events ^!g[state(S)[reason(R)]]: a goal's life (pending, executing, achieved,
// finished), a failure handled by a -!g plan, .suspend/.resume of a goal still an event, and
// .fail_goal/.succeed_goal.
!main.
+!main <- !ok; !bad; !!later; .suspend(later); .resume(later);
          .wait(50); !!long(1); .wait(20); !!long(2); .wait(20); .fail_goal(long(1)); .wait(20); .succeed_goal(long(2));
          .wait(100); .stopMAS.
+!ok.
+!bad <- .fail.
-!bad.
+!later.
+!long(_) <- .wait(1000).
-!long(_).
^!ok[state(S)] <- .print(ok, " ", S).
^!bad[state(S)[reason(R)]] <- .print(bad, " ", S).
^!later[state(S)] <- .print(later, " ", S).
^!long(N)[state(S)] : S \== waiting <- .print(long(N), " ", S).
