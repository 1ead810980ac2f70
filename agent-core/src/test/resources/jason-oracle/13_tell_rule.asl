// A performative of one's own through +!kqml_received (tellRule), rules added by +R[source(S)]
// with R a rule term, rules printed as terms ({ h :- b }) and .relevant_rules with the rules'
// own variable names, or of every rule.
b.
c.
x(V) :- V > 10.
!t.
+!kqml_received(S, tellRule, Rules, _) <- for (.member(R, Rules)) { +R[source(S)] }; .print(received(Rules, S)).
+!t <- .my_name(Me); .send(Me, tellRule, [{a :- b & c}]); .wait(100);
       if (a) { .print(a_holds) };
       .relevant_rules(x(_), L); .print(L);
       .relevant_rules(a, L2); .print(L2);
       R = {q :- b}; .print(R); .print([R]);
       .stopMAS.
