// Jason's .set.*, .queue.* and .map.* internal actions: sets print as {a,b} in the standard order,
// maps as {k->v} by key, queues as Java's [a, b] (a priority queue in its heap's order); .length
// counts them, .member walks sets and queues, == and = compare sets by contents and maps by
// identity, and sets, queues and maps sort after structures, as they print. A for over .map.key or
// .member goes through the collection as it was when the loop began.
!t.
+!t <- .set.create(S); .set.add_all(S, [c, a, b, f(1), 3, "s"]); .print(S); .print("S=", S);
   .length(S, L); .print(L);
   .set.remove(S, a); .set.remove(S, zz); .print(S);
   .set.to_list(S, SL); .print(SL); .set.to_list(S, [H|T]); .print(H, " ", T);
   .set.create(S2); .set.add_all(S2, [b, x, 3]);
   .set.copy(S, S3); .set.add(S3, new); .print(S, " ", S3);
   .set.union(S3, S2); .print(S3, " ", S2);
   .set.copy(S, S4); .set.intersection(S4, S2); .print(S4);
   .set.copy(S, S5); .set.difference(S5, S2); .print(S5);
   .set.copy(S, S6); .set.union(S6, [z, 4]); .set.difference(S6, [c, "s"]); .set.intersection(S6, [z, 3, b, f(1), q]); .print(S6);
   .set.clear(S5); .print(S5); .length(S5, L5); .print(L5);
   .term2string(S, TS); .print(TS);
   .findall(X, .member(X, S), FL); .print(FL);
   .set.create(A); .set.add_all(A, [b, a]); .set.create(B); .set.add_all(B, [a, b]);
   if (A == B) { .print(same_set) }; if (A = B) { .print(sets_unify) };
   .sort([A, b, 1, "x", [a], f(a)], Sorted); .print(Sorted);
   if (.set.create(A)) { .print(created_again) } else { .print(create_bound_fails) };
   !queues; !maps; !mixed; !loops;
   .stopMAS.

+!queues <- .queue.create(Q); .queue.add_all(Q, [z, y, x]); .print(Q); .length(Q, QL); .print(QL);
   .queue.to_list(Q, QT); .print(QT); .queue.copy(Q, Q2); .queue.add(Q2, w); .print(Q, " ", Q2);
   .queue.remove(Q2, R); .print(R, " ", Q2);
   .findall(E, .member(E, Q2), EL); .print(EL);
   .queue.clear(Q); .print(Q); .length(Q, QL0); .print(QL0);
   if (.queue.head(Q, _)) { .print(head) } else { .print(empty_queue) };
   .queue.create(P, priority); .queue.add_all(P, [c, a, b]); .print(P); .queue.to_list(P, PL); .print(PL);
   .queue.copy(P, P2); .queue.add(P2, aa); .queue.remove(P2, R1); .print(R1, " ", P2, " ", P);
   .queue.remove(P2, R2); .print(R2); .queue.clear(P2); .print(P2);
   .term2string(P, TP); .print(TP).

+!maps <- .map.create(M); .map.put(M, b, 2); .map.put(M, a, 1); .map.put(M, c, f(x)); .print(M); .print("M=", M);
   .length(M, ML); .print(ML);
   .map.get(M, a, V1); .print(V1);
   .map.put(M, a, 10); .map.get(M, a, V2); .print(V2);
   if (.map.get(M, zz, V3)) { .print(got, V3) } else { .print(no_key) };
   .map.get(M, zz, V4, none); .map.get(M, b, V5, none); .print(V4, " ", V5);
   if (.map.get(M, _, _)) { .print(free_key) } else { .print(free_key_fails) };
   .findall(K, .map.key(M, K), KL); .print(KL);
   .findall(V, .map.value(M, V), VL); .print(VL);
   .map.key(M, K1); .map.value(M, V6); .print(K1, " ", V6);
   if (.map.key(M, c)) { .print(key_c) }; if (.map.key(M, zz)) { .print(key_zz) };
   if (.map.value(M, 2)) { .print(value_2) }; if (.map.value(M, 3)) { .print(value_3) };
   .map.copy(M, M2); .map.remove(M2, b, RV); .print(RV, " ", M, " ", M2);
   if (.map.remove(M2, zz, _)) { .print(removed) } else { .print(nothing_to_remove) };
   .map.clear(M2); .print(M2); .length(M2, ML2); .print(ML2);
   .map.put(N, f(2), [1, 2]); .map.put(N, f(1), "one"); .map.put(N, "s", g(Y)); .map.put(N, 7, [a]);
   .print(N); .findall(p(I), .map.key(N, f(I)), PL); .print(PL);
   .term2string(N, TN); .print(TN);
   .map.create(MA); .map.put(MA, k, 1); .map.create(MB); .map.put(MB, k, 1); if (MA == MB) { .print(same_map) } else { .print(maps_differ) };
   if (MA = MB) { .print(maps_unify) } else { .print(maps_do_not_unify) }; if (MA == MA) { .print(same_map_itself) }.

+!mixed <- .set.create(S); .map.create(M); .map.put(M, k, v); .queue.create(Q); .queue.add(Q, a);
   .set.add(S, M); .set.add(S, Q); .print([S, M, Q]);
   .sort([M, S, Q], L); .print(L); .term2string([S], T); .print(T).

+!loops <- .map.put(M, a, 1); .map.put(M, b, 2);
   for (.map.key(M, K)) { .map.get(M, K, V); .print(K, " ", V); .map.put(M, c, 3) };
   .print(M); .map.remove(M, c, _);
   .findall(p(K2, V2), .map.key(M, K2) & .map.get(M, K2, V2), L); .print(L);
   .set.add_all(S, [a, b]); for (.member(X, S)) { .print(X); .set.add(S, c) }; .print(S).
