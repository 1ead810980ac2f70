// .succeed_goal on a goal deep in another intention's stack.
!main. !ctl.
+!main <- !outer; .print("main goes on"); .stopMAS.
+!outer <- !inner; .print("outer after inner").
+!inner <- .wait({+never}).
+!ctl <- .wait(5); .succeed_goal(outer).
