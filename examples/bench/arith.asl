// 30 000 turns of arithmetic in a plan body: math functions, mod, div, ** and a running sum.
!go.
+!go <- .print(start); !a(0, 0).
+!a(30000, S) <- .print(end); .stopMAS.
+!a(N, S) <- X = math.sqrt(N) + math.abs(-N) * 2 / 3 - N mod 7 + (N div 3) ** 2; !a(N + 1, S + X).
