// A failure inside a failure plan goes on to the next goal below with a failure plan.
!start.
+!start <- !a; .print("start goes on"); .stopMAS.
-!start <- .print("-!start"); .stopMAS.
+!a <- !b; .print("not printed").
-!a[error(E)] <- .print("-!a ", E).
+!b <- .fail.
-!b <- .print("-!b then fails"); .fail.
