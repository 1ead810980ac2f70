// .verbose, .perceive and .print_unifier (Jason 3.2.0)
!start.
+!start <- !verbosity; !perception; !unifiers; !wrong; .stopMAS.
+!verbosity <- .verbose(1); .print(verbose_one); .verbose(1, ignored); .print(extra_argument_ignored).
+!perception <- .perceive; .print(perceived).
+!unifiers <- !none; !one; !struct; !args(7).
+!none <- .print_unifier.
+!one <- X = 3; .print_unifier.
+!struct <- Y = f(Z, "s", [1, a]); .print_unifier.
+!args(N) <- .print_unifier(foo, bar).
+!wrong <- !w(.perceive(a)); !w(.perceive(a, b)).
+!w(A) <- A; .print(not_failed, A).
-!w(A)[error(E)] <- .print(failed, " ", E).
