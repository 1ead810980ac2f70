// .asserta/.assertz (where they add, their events with a new focus, source(self) from asserta
// only), .belief (facts only, not rules), .add_nested_source and .remove_source_annot
e(1).
r(X) :- e(X).

!main.

+!main
   <- .asserta(e(0)); .print(after_asserta);
      .assertz(e(2)); .print(after_assertz);
      .wait(100);
      .findall(X, e(X), L); .print(L);
      +e(3); .assertz(e(1)); .asserta(e(2)); .wait(100);
      .findall(X, e(X), L2); .print(L2);
      .asserta(g(1)[source(p), a]); ?g(1)[source(S)]; .print(S);
      ?g(1)[a, source(p)]; .print("kept a");
      .assertz(h(1)); .asserta(h(0)); .findall(A, h(_)[source(A)], Hs); .print(Hs);
      .asserta(~e(7)); .findall(X, ~e(X), L3); .print(L3);
      for (.belief(e(X))) { .print(belief, " ", X) };
      .belief(g(1)[source(S2)]); .print(S2);
      if (.belief(r(_))) { .print(wrong) } else { .print("no rule is a belief") };
      if (.belief(e(9))) { .print(wrong) } else { .print("no e(9)") };
      .add_nested_source(x, s, N1); .print(N1);
      .add_nested_source([a, b[x], c[source(t)], 1, "q"], s, N2); .print(N2);
      .add_nested_source(x[source(p), source(q)], f(y), N3); .print(N3);
      .add_nested_source(~a[source(x)], s, N4); .print(N4);
      .add_nested_source(a[b], s, a[source(s), b]); .print(matched);
      .remove_source_annot(a[source(x), y], R1); .print(R1);
      .remove_source_annot(a[source(x), source(y), y], R2); .print(R2);
      .remove_source_annot([a[source(x)], 1, b], R3); .print(R3);
      .remove_source_annot(~b[source(x), c], R4); .print(R4);
      if (.remove_source_annot(a[source(x)], b)) { .print(wrong) } else { .print("a is not b") };
      .stopMAS.

+e(X)[source(self)] <- .print(added, " ", X).
+e(X) <- .print(added, " ", X, " without a source").
