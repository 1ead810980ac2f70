// .empty, .shuffle (its result's properties: Jason's order is random), .copy_term, .rename_apart,
// and .nano_time, .date and .version (what they bind, not the values of the day)
!main.

+!main
   <- for (.member(T, [[], "", [a], "a", a, 0, f(x)])) {
         if (.empty(T)) { .print(T, " empty") } else { .print(T, " not empty") }
      };
      .shuffle([a,b,c,d,e,f], Sh); .length(Sh, N); .sort(Sh, Sorted); .print(N, " ", Sorted);
      .shuffle([], Sh0); .print(Sh0);
      .shuffle([x], [x]); .print("one element");
      !try(shuffle(x));
      !try(shuffle(Unbound));
      .copy_term(f(X, Y, X, g(Z)), C);
      C = f(1, 2, Q, W);
      .print(Q, " ", W, " ", X, " ", Y);
      .copy_term(a, a); .copy_term([a, L, L], CL); CL = [_, 3, M]; .print(M);
      .copy_term(h(A)[n(A)], D); D = h(B)[n(9)]; .print(B, " ", A);
      .copy_term(V, V2); V = 7; .print(V2);
      .rename_apart(k(K, K), R); R = k(5, O); .print(O, " ", K);
      .rename_apart(U, U2); U = 8; .print(U2);
      .nano_time(T1); .nano_time(T2);
      if (T1 > 0 & T2 >= T1) { .print("nano_time grows") };
      .date(Yr, Mo, Dy);
      if (Yr >= 2024 & Mo >= 1 & Mo <= 12 & Dy >= 1 & Dy <= 31) { .print("a date") };
      .time(_, _, _);
      .version(Ver); .print(Ver);
      if (Ver == "3.2.0") { .print("the version is a string") };
      if (.nano_time(1)) { .print(wrong) } else { .print("nano_time(1) fails") };
      if (.date("a", _, _)) { .print(wrong) } else { .print("date(\"a\", _, _) fails") };
      .stopMAS.

+!try(shuffle(L)) <- .shuffle(L, _).
-!try(G)[error(E)] <- .print(G, " ", E).
