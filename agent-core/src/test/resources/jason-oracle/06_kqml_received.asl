// Messages through +!kqml_received (Jason's kqmlPlans): an askOne the belief base cannot answer
// goes to a +? plan (false when it fails), the agent's own kqml_received plans customise a
// performative or add one, other failures print a communication error, askHow answers plan terms, and a plan term's body prints bare.
vl(10).
+?t2(X) : vl(Y) <- X = 10 + Y.
+?t3(X) <- ?nothing(X).
+?t5(X) <- .fail.
+!kqml_received(S, askOne, fullname, M) <- .send(S, tell, "Maria dos Santos", M).
+!kqml_received(S, greet, C, _) <- .print("greeted with ", C, " by ", S).
+!goto(X, Y)[source(A)] <- .print(goto(X, Y), A).
!t.
+!t <- .my_name(Me);
       .send(Me, askOne, t2(_), A1); .print(A1);
       .send(Me, askOne, t3(_), A2); .print(A2);
       .send(Me, askOne, t4(_), A3); .print(A3);
       .send(Me, askOne, vl(_), A4); .print(A4);
       .send(Me, askOne, fullname, A5); .print(A5);
       .send(Me, greet, hello); .wait(100);
       .send(Me, askOne, t5(_)); .wait(100);
       .send(Me, askHow, {+!goto(_, _)}, [P]);
       P = {@L +!T : C <- B};
       if (T = goto(_, _)[source(_)]) { .print(trigger_ok) };
       .print(C);
       .substring(".print(", B, 0); .print(body_starts_with_print);
       .relevant_plans({+!goto(_, _)}, Ps); .length(Ps, N); .print(N);
       .stopMAS.
