// Plan contexts that start with a comparison, false for most of a goal's plans: the first
// applicable plan, in file order, with its bindings, whatever kinds of terms are compared.
b(4, four). b(5, five).
!start.
+!pick(N) : N > 3 & b(N, X) <- .print(big(N, X)).
+!pick(N) : N == 2 <- .print(two).
+!pick(N) : N \== 2 & N < 2 & N >= 1 <- .print(one).
+!pick(N) : X = N & X == 3 <- .print(three(X)).
+!pick(N) : N == a | N == b <- .print(letter(N)).
+!pick(N) : "s" < N & N \== z <- .print(after_strings(N)).
+!pick(N) : f(N) == f(c) <- .print(f_of_c).
+!pick(N) : [N] == [[]] <- .print(empty_list).
+!pick(N) : N * 2 - 1 == -1 & true <- .print(zero).
+!pick(N) : N > 6 & N < 9 & N \== 7.5 <- .print(seven_to_nine(N)).
+!pick(N) <- .print(other(N)).
+!start <-
    for (.member(V, [0, 1, 2, 3, 4, 5, 6, 7, 7.5, 8, a, b, c, d, z, "str", [], g(1)])) { !pick(V) };
    Y = 8; !pick(Y);
    .stopMAS.
