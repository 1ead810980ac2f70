// .relevant_plan(Trigger, Plan): each relevant plan in turn; and .get_src_info(L, R).
!start.

b(1).

@pa +!a(X) : X > 0 <- .print(pos(X)).
@pb +!a(X) <- .print(any(X)).
+!c <- true.

+!start
   <- .relevant_plan({+!a(_)}, P1); .print(P1);
      .findall(P, .relevant_plan({+!a(3)}, P), L); .length(L, N); .print(count(N));
      for (.relevant_plan({+!a(Y)}, P2)) { .print(each(P2)) };
      if (.relevant_plan({+!nothing}, _)) { .print(some) } else { .print(none) };
      .relevant_plan({+!c}, P3); .print(P3);
      .relevant_plan(T, P1); .print(trigger(T));
      .get_src_info(b(2), S1); .print(S1);
      .get_src_info(b(2)[x], S2); .print(S2);
      X = c(3); .get_src_info(X, S3); .print(S3);
      ?b(V); .get_src_info(b(V), S4); .print(S4);
      .stopMAS.
