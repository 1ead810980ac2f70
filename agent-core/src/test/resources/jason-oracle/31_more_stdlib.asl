// .verbose, .perceive, .print_unifier, .signal, .internal_action and .done (Jason 3.2.0)
!start.
+!start <- !verbosity; !perception; !unifiers; !signals; !ias; !dones; !wrong; .stopMAS.
+!verbosity <- .verbose(1); .print(verbose_one); .verbose(1, ignored); .print(extra_argument_ignored).
+!perception <- .perceive; .print(perceived).
+!unifiers <- !none; !one; !struct; !args(7).
+!none <- .print_unifier.
+!one <- X = 3; .print_unifier.
+!struct <- Y = f(Z, "s", [1, a]); .print_unifier.
+!args(N) <- .print_unifier(foo, bar).
// a signalled trigger is an event as is: no source, no belief added, a new intention
+!signals <- .signal({+!sig(1)}); .signal({+sb(2)}); .signal({-sc}); .signal({+?sq}); .signal({+!sig(3)[x]});
  .print(signalled); .wait(200); !check.
+!sig(N)[A] <- .print(sig_annotated, N, A); !depth.
+!sig(N) <- .print(sig, N); !depth.
+!sig(N)[source(S)] <- .print(never, S).
+!depth <- .intention(_, _, S, current); .length(S, K); .print(stack, K).
+sb(N) <- .print(sb, N).
-sc <- .print(minus_sc).
+?sq <- .print(sq).
+!check <- ?sb(_); .print(believed).
-!check <- .print(sb_not_believed).
// .internal_action: only a call of a known internal action
+!ias <- !w(.internal_action(.print)); !w(.internal_action(.my_name(N))); Y = .print(y); !w(.internal_action(Y));
  !w(.internal_action(".print")); !w(.internal_action(print)); !w(.internal_action(Z)); !w(.internal_action(foo(x)));
  !w(.internal_action(3)); !w(.internal_action([.print])); !w(.internal_action(.nonexist(x))).
// .done: the current goal, or a goal of this intention, achieved; another goal ends the intention silently
+!dones <- !dn(a); .print(after_dn_a); !dn2; .print(after_dn2); !dr(2); .print(after_dr); !!dn_lost; .wait(100); .print(dones_end).
+!dn(a) <- .done; .print(never).
+!dn2 <- !dn3; .print(never).
+!dn3 <- .done(dn2); .print(never).
+!dr(0) <- .done.
+!dr(N) <- !dr(N - 1); .print(dr_after, N).
+!dn_lost <- !dn4; .print(never).
+!dn4 <- .done(nothing); .print(never).
^!G[state(S)] : .member(G, [dn(_), dn2, dn3, dr(_), dn_lost, dn4]) & (S == achieved | S == finished | S == dropped) <- .print(G, " ", S).
+!wrong <- !w(.perceive(a)); !w(.perceive(a, b)); !w(.signal({+a}, b)); !w(.internal_action(.print(x), 2)); !w(.done(1)); !w(.done(a, b)).
+!w(A) <- A; .print(not_failed, A).
-!w(A)[error(E)] <- .print(failed, " ", E).
