// Test goals on rules with arithmetic, backtracking into later solutions, and +? plans.
v(1). v(5). v(9).
big(X) :- v(X) & X > 4.
!start.
+!start <- ?big(A); .print(A); .findall(B, big(B), L); .print(L); ?missing(M); .print(M); .stopMAS.
+?missing(42).
