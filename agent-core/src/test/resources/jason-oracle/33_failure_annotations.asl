// The annotations of failure events: .fail with arguments, .fail_goal of an enclosing goal,
// and a goal with no relevant plan when a failure plan with a variable trigger exists.
!start.

+!start
   <- !a1; !a2; !a3;
      for (.member(G, [b1, b2, b3, c, d, e(1)])) { !!run(G); .wait(50) };
      .stopMAS.

// each case in an intention of its own: after the failure plan of a goal ended by .fail_goal,
// Jason goes on below that goal's caller
+!run(G) <- !G; .print(after(G)).

// .fail with arguments: they join Jason's error annotations
+!a1 <- .fail(reason(x), other).
-!a1[error(E), error_msg(M), reason(R)] <- .print(a1(E, M, R)).
+!a2 <- .fail(error(custom), error_msg("my message"), reason(y)).
-!a2[error(E), error_msg(M), code(C), code_line(L)] <- .print(a2(E, M, C, L)).
+!a3 <- X = 1; .fail(val(X)).
-!a3[val(V), error(E)] <- .print(a3(V, E)).

// .fail_goal of an enclosing goal
+!b1 <- !b1_sub.
+!b1_sub <- .fail_goal(b1).
-!b1[error(E), error_msg(M)] <- .print(b1_failed(E, M)).
-!b1 <- .print(b1_failed_other).

+!b2 <- !b2_sub; .print(b2_never).
+!b2_sub <- .print(b2_sub); .fail_goal(b2); .print(b2_sub_after).
-!b2[code(C), code_line(L)] <- .print(b2_failed(C, L)).
-!b2 <- .print(b2_failed_no_code).

+!b3 <- !b3_sub; .print(b3_never).
+!b3_sub <- .fail_goal(b3_sub).
-!b3_sub[error(E)] <- .print(b3_sub_failed(E)).
-!b3_sub <- .print(b3_sub_failed).

// no relevant plan for !missing(1), and a failure plan with a variable trigger
+!c <- !missing(1); .print(c_after_missing).
+!d <- ?nothing(X); .print(d_after).
+!e(X) : X > 5 <- .print(e).
// posted through the variable of !G: its caller ends with the failure plan, as in Jason
-!e(X)[error(E), code(C)] <- .print(e_failed(X, E, C)).
-!G : .print(trying(G)) & G \== foo <- .print(failed(G)).
