// Plans as terms: .relevant_plans and .add_plan.
!start.
+!start <- .relevant_plans({+!g(_)}, P); .length(P, N); .print(N);
    .add_plan({+!h(X) : X > 1 <- .print("h ", X)}); !h(5); .stopMAS.
@p1 +!g(1) <- .print(one).
+!g(X) : X > 2 <- .print(big).
