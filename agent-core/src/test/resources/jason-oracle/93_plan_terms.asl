!g.
@lp[atomic] +!t(X) : X > 0 <- .print(t, X); .print(done).
+!g <- .relevant_plans({+!t(_)}, [P|_]); P = {@L +!T : C <- B}; if (L = lp[atomic]) { .print(label_ok) }; if (T = t(Z) & C = (Z2 > 0)) { .print(trigger_ok) };
       P =.. [L2, Tr, C2, B2]; if (Tr = {+!t(_)}) { .print(univ_ok) };
       N =.. [k, {+!w(Y)}, true, {.print(w, Y)}]; .add_plan(N); !w(3);
       .findall(Lb, .relevant_plans({+!_}, LP, _) & .member(Q, LP) & Q = {@Lb +!t(_) : _ <- _}, Ls); .length(Ls, Len); .print(Len);
       !walk(B);
       .stopMAS.
+!walk({}) <- .print(end).
+!walk({H; R}) <- .print(step); !walk(R).
