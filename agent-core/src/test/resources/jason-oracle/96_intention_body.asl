// The body in .intention's stack is the plan's text (not instantiated, variables fresh):
// equal steps written on different lines are one belief, steps with variables never are.
// A step taken by {T; _} prints as the bare formula, the rest with braces.
!t.
+!t <- !a(1);
       !a(1);
       X = 2;
       !b(X);
       !b(X);
       .count(seen(_), N); .print(N);
       for (seen(S) & .ground(S)) { .print(S) }
       {.print(x); .print(y); .print(z)} = {F; R};
       .print(F); .print(R);
       .stopMAS.
+!a(_) : .intention(_,_,[im(_,_,{T; _},_)|_],current) <- +seen(T).
+!b(_) : .intention(_,_,[im(_,_,{T; _},_)|_],current) <- +seen(T).
