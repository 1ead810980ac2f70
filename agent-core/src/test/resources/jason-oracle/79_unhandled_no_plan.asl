// A subgoal with no plan and no failure plan: Jason reports it twice and drops the intention.
!start.
+!start <- !g; .print(after).
+!g <- .print(g1); !missing(1); .print(never).
+!stop <- .wait(300); .print(stopping); .stopMAS.
!stop.
