// Plan contexts with strings, lists and not over rules with several solutions.
p("a", [1, 2]).
p("b", [3]).
len(L, N) :- .length(L, N).
!start.
+!start : p(S, L) & len(L, 1) <- .print(S); !next.
+!start <- .print(none).
+!next : not (p(_, L) & len(L, 3)) <- .print(ok); .stopMAS.
