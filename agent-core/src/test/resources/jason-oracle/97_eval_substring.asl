// .eval gives true/false for a formula; .substring's forms: test, every position (with an end),
// extraction with an unbound first argument, and terms taken as their text.
b(1). b(2).
!t.
+!t <- .eval(X1, b(_) & not b(3)); .print(X1);
       .eval(X2, b(5) | 3 > 4); .print(X2);
       if (.eval(true, b(2))) { .print(eval_true) };
       for (.substring("a", "abbacca", P)) { .print(at, P) };
       for (.substring("ab", "xabab", P2, E2)) { .print(P2, "-", E2) };
       .substring(S1, a(10,20), 5); .print(S1);
       .substring(S2, "hello world", 0, 5); .print(S2);
       .substring(f(1), g(x, f(1)), Q); .print(Q);
       if (not .substring("z", "abc")) { .print(no_z) };
       .current_intention(intention(Id, [im(L, _, _, _)|_])); if (.substring(p__, L, 0)) { .print(label_ok) };
       .stopMAS.
