// Plans with a goal condition (<:) as terms: printed, copied by .relevant_plans, added from a string.
!start.

@gc +!count(N) : N < 10 <: done(N) <- .print(step(N)); +done(N); .wait(50); .print(after(N)).

+!start
   <- .relevant_plans({+!count(_)}, L); .print(L);
      L = [P|_];
      .term2string(P, S); .print(S);
      .plan_label(P2, gc); .print(P2);
      .add_plan("@gs +!other(X) <: stop(X) <- .print(other(X)); +stop(X); .wait(50); .print(never).");
      .relevant_plans({+!other(_)}, L2); .print(L2);
      !other(1);
      .print(other_ended);
      .remove_plan(gc);
      .add_plan(P);
      !count(2);
      .print(count_ended);
      .stopMAS.
