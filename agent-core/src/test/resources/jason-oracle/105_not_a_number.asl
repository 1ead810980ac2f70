// Arithmetic over an operand bound to what is no number: NaN, with Jason's
// [ArithExpr] warning; an operand still free leaves the expression as written,
// and so does a function whose argument is free.
v(a).
w(1).
!start.
+!start <- X = a; S = "s"; F = f(1);
   .print(p1, X + 1); .print(p2, X + Z); .print(p3, Z + X); .print(p4, (Z + 1) * X);
   .print(p5, -X); .print(p6, F + 1); .print(p7, 1 + S); .print(p8, 2 ** X);
   .print(p9, X div 2); .print(p10, 7 mod X); .print(p11, (X * 2) + 1);
   N = X + 1;
   if (N == N) { .print(eq) } else { .print(neq) }
   if (N == 3) { .print(eq3) } else { .print(neq3) }
   if (N > 3) { .print(gt) } else { .print(ngt) }
   if (N < 3) { .print(lt) } else { .print(nlt) }
   if (N >= 3) { .print(ge) } else { .print(nge) }
   if (N <= 3) { .print(le) } else { .print(nle) }
   if (N = N) { .print(un) } else { .print(nun) }
   M = N * 0; .print(m, M); .print(abs, math.abs(N));
   .sort([3, N, 1], L); .print(sorted, L);
   +c(X * 3); ?c(C); .print(c, C);
   for (.member(E, [1, b])) { .print(e, E + 1) }
   !g1; !g2; !g3(X - 1); !g4(Y + 1);
   K = 3; .print(f1, math.max(K, W)); .print(f2, math.abs(W) + K);
   .print(done); .stopMAS.
+!g1 : v(X) & X + 1 > 2 <- .print(g1a).
+!g1 <- .print(g1b).
+!g2 : v(X) & w(Y) & Y < X * 2 <- .print(g2a).
+!g2 <- .print(g2b).
+!g3(V) <- .print(g3, V).
+!g4(V) <- .print(g4, V); V = U; .print(u, U).
-!start <- .print(failed); .stopMAS.
