// 300 turns of list work: .findall over .range, a recursive sum rule, .length, .nth, .concat.
sum([], 0).
sum([H|T], S) :- sum(T, S1) & S = S1 + H.
!go.
+!go <- .range(L0, 1, 300); .findall(X, .member(X, [1,2,3,4,5,6,7,8,9,10]), _); .print(start); !loop(0).
+!loop(300) <- .print(end); .stopMAS.
+!loop(N) <- .findall(X, .range(X, 1, 300), L); ?sum(L, S); .length(L, Len); .nth(5, L, E); .concat(L, [S], L2); !loop(N + 1).
