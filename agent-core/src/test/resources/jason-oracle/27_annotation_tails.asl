// A tail in a literal's annotations, b(1)[x|A] and b(1)[|A], as Jason reads and matches it.
b(1)[x, y].
b(2).
p(1)[a, b].

!start.

+!start <-
  .findall(A, b(1)[x|A], L1); .print(L1);
  .findall(A, b(1)[source(self)|A], L2); .print(L2);
  .findall(A, b(1)[|A], L3); .print(L3);
  .findall(A, b(X)[|A], L4); .print(L4);
  .findall(b(X)[|A], b(X)[|A], L5); .print(L5);
  .findall(b(X)[x|A], b(X), L6); .print(L6);
  .findall(A, b(X)[z|A], L7); .print(L7);
  ?b(1)[y|R1]; .print(R1);
  if (b(1)[z|R2]) { .print(yes, R2) } else { .print(no_z) };
  if (b(1)[x, y|R3]) { .print(xy, R3) } else { .print(no_xy) };
  ?p(1)[S|R4]; .print(S, " ", R4);
  .findall(r(S2, R5), p(1)[S2|R5], L8); .print(L8);
  !query(x);
  !query(w);
  X1 = c[|T1]; .print(X1);
  X2 = c(1)[a|T2]; .print(X2);
  .print(e[x, y|T3], " ", ~e[|T4], " ", ns::e[a|T5], " ", e(1)[z|[]]);
  d[a, b] = d[a|T6]; .print(T6);
  d[a|T7] = d[a, b, c]; .print(T7);
  d[a|T8] = d[b|T9]; .print(T8, " ", T9);
  d[a, c|T10] = d[b|T11]; .print(T10, " ", T11);
  d[|T12] = d[a]; .print(T12);
  d = d[|T13]; .print(T13);
  if (V[|R6] = e(1)[a, b]) { .print(V, " ", R6) } else { .print(no_var) };
  if (d[|T14] = d) { .print(yes, T14) } else { .print(no_empty) };
  if (d[a|T15] = d[b, c]) { .print(yes, T15) } else { .print(no_a) };
  if (d[a|T16] = d[a, b|U16]) { .print(T16, " ", U16) } else { .print(no) };
  Z1 = d[x|T17]; T17 = [y, w]; .print(Z1);
  Z2 = d[x|T18]; T18 = [y|T19]; .print(Z2);
  Z3 = d(1)[x|T20]; T20 = [a, x]; .print(Z3);
  if (d[|T21] == d[|T21]) { .print(same) } else { .print(not_same) };
  if (d[|T22] == d) { .print(same) } else { .print(not_same) };
  if (d[a|[]] == d[a]) { .print(same) } else { .print(not_same) };
  d(1)[a|T23] =.. U; .print(U);
  .term2string(f[k|T24], Str); .print(Str);
  +h(1)[a, b];
  +f(5)[q];
  .send(annotation_tails, tell, g(7)[k]);
  .wait(200);
  .print(done);
  .stopMAS.

+!query(K) : b(1)[K|R] <- .print(query(K, R)).
+!query(K) <- .print(query(K, none)).

+h(X)[source(S)|R] <- .print(h(X, S, R)).
+f(X)[|R] : b(1)[y|Q] <- .print(f(X, R, Q)).
+b(X)[source(S)|R] <- .print(b(X, S, R)).
+g(X)[source(S)|R] <- .print(g(X, S, R)).
