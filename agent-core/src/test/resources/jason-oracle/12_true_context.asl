// A plan context that is just true is no context (Jason's parser drops it), in plans and in plan
// terms; a conjunction with true stays.
!start.
+!g1 : true <- .print(a).
+!g2 : true & true <- .print(b).
+!g3 : (true) <- .print(c).
+!start <- .relevant_plans({+!g1}, L1); .print(L1);
           .relevant_plans({+!g2}, L2); .print(L2);
           .relevant_plans({+!g3}, L3); .print(L3);
           P = {+!g4 : true <- .print(d)}; .print(P);
           .add_plan(P); .relevant_plans({+!g4}, [Q]); Q = {@_ +!g4 : C <- _}; .print(C);
           .stopMAS.
