// .plan_label both ways, .remove_plan with sources and lists, +{rule} and .relevant_rules.
!t.
+!t <- .add_plan({ @l1 +!p1 : true <- +p1 }, bob);
       .plan_label(P1, l1); if (P1 == { @l1[source(bob)] +!p1 <- +p1 }) { .print(same_plan) };
       .plan_label({ @l2[x] +!p2 <- +p2 }, L2); .print(L2);
       .add_plan({ @k1 +!q <- true }, bob); .add_plan({ @k2 +!q <- true }); .add_plan({ @k3 +!q <- true }, bob);
       .remove_plan(k2, bob); .relevant_plans({+!q}, _, A); .length(A, NA); .print(NA);
       .remove_plan([k1, k2, k3], bob); .relevant_plans({+!q}, _, B); .print(B);
       .remove_plan(B); .relevant_plans({+!q}, _, C); .print(C);
       .relevant_rules(r(_,_), R0); .print(R0);
       +{ r(X, Y) :- Y = X + 1 };
       .relevant_rules(r(_,_), R1); .length(R1, NR1); .print(NR1);
       ?r(10, Y1); .print(Y1);
       .stopMAS.
