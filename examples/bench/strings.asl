// 20 000 turns of string work: .concat, .length, .term2string both ways, .substring.
!go.
+!go <- .print(start); !s(0, "").
+!s(20000, _) <- .print(end); .stopMAS.
+!s(N, Acc) <- .concat("x", N, S); .length(S, L); .term2string(T, S); .substring("x", S, P); !s(N + 1, S).
