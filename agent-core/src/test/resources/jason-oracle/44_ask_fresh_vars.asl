// The fresh variables (_N) an ask takes when the default plans answer it, shown by the
// variables .relevant_plans renames after each ask.
vl(1). vl(2). w(1)[a,b]. w(2)[source(x)].

!start.

+!start <- .my_name(Me); !show(start);
   .send(Me, askOne, vl(X), A1); .print(A1); !show(ask_one_var);
   .send(Me, askOne, vl(1), A2); .print(A2); !show(ask_one_ground);
   .send(Me, askOne, vl(_)); .wait(50); !show(ask_one_async);
   .send(Me, askOne, zz(_,_), A3); .print(A3); !show(ask_one_unknown);
   .send(Me, askOne, zz(1), A4); .print(A4); !show(ask_one_unknown_ground);
   .send(Me, askOne, t2(_,_), A5); .print(A5); !show(ask_one_by_test_plan);
   .send(Me, askOne, w(_), A6); .print(A6); !show(ask_one_annotations);
   .send(Me, askOne, w(2), A7); .print(A7); !show(ask_one_other_source);
   .send(Me, askOne, vl(Y)[source(S)], A8); .print(A8); !show(ask_one_named_source);
   .send(Me, askOne, vl(Z)[foo], A9); .print(A9); !show(ask_one_missing_annotation);
   .send(Me, askAll, vl(_), L1); .print(L1); !show(ask_all);
   .send(Me, askAll, w(_), L2); .print(L2); !show(ask_all_annotations);
   .send(Me, askAll, zz(_), L3); .print(L3); !show(ask_all_none); .stopMAS.

+vl(X)[source(S)] : S \== self <- .print("told ", X, " by ", S).
+?t2(3,4).

+!show(Step) <- .relevant_plans({+!probe(_)}, [P]); .print(Step, " ", P).
@probe +!probe(A) <- .print(A).
