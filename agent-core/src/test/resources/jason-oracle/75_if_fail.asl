// A failure inside an if branch fails the plan; the failure plan continues after the goal.
!start.
+!start <- !g; .print(after); .stopMAS.
+!g <- if (true) { .print(in); .fail } ; .print(never).
-!g <- .print(recovered).
