// Rules calling internal actions and findall inside rule bodies.
n(3). n(1). n(2).
sorted(L) :- .findall(X, n(X), L0) & .sort(L0, L).
total(T) :- .findall(X, n(X), L) & sumlist(L, T).
sumlist([], 0).
sumlist([H|R], S) :- sumlist(R, S0) & S = S0 + H.
!start.
+!start <- ?sorted(L); .print(L); ?total(T); .print(T); .stopMAS.
