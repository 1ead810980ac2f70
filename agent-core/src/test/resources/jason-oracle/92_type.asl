!g.
+!g <- for (.member(X, [1, 1.5, "s", a, f(x), [a], [], ~a, b[x], {+!g}, {a;b}, (1+X2), Y])) { .type(X, T); .print(T) }; .stopMAS.
