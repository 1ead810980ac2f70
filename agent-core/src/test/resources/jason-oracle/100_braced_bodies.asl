// braced bodies written as formulas are flattened into the body round them; the bodies that
// statements and forks make print bare, a body written as a term keeps its braces
!start.
@p1 +!start <- { .print(a); .print(b) }; .print(c); { .print(d) } |&| .print(e); !show.
+!show <- .relevant_plans({+!start}, [P]); .print(P);
   .print({ if (true) { .print(x); .print(z) } elif (b) { .print(y) } else { .print(w); !g } });
   .print({ while (a) { .print(x); +b } });
   .print({ for (.member(A, [1])) { if (A > 0) { .print(A) } } });
   .print({ .print(x) ||| { .print(y); .print(z) } });
   .print({ if (true) { } else { .print(q) } }, " ", { .if_then_else(true, { .print(q) }) });
   .print(f({ .print(x) }, { a; b }), " ", { { .print(a) }; .print(b) });
   .stopMAS.
