// Fresh variables are numbered as Jason numbers its unnamed variables: one counter for the whole
// system, from which each _ read, the 18 of Jason's kqmlPlans.asl per agent, a goal's variables and
// every renaming draw.
p(_, a).
!g(X).
+!g(Y) <- .print(start);
          +b(Z)[n(K)]; ?b(W);
          .relevant_plans({+!h(_)}, L); .print(L);
          .list_plans({+!h(_)});
          .plan_label(P, hl); .print(P);
          -+c(1, 2);
          .stopMAS.
@hl +!h(A)[source(S)] <- .print(A, S, _).
