// .intention's stack: each unifier in the order of Jason's hash map of variable names, keys named
// after their variables (_N, or _NName), values as bound (a variable stays the intention's own, so
// a binding made later by the failure plan shows through it; a structure's variables are fresh).
!test.
+!test <- !g1(X); .print(end(X)).
+!g1(Result) <- Pair = p(A, B); Long = f(Pair); !g2(Result, Pair).
+!g2(Out, p(First, _)) <- .fail.
-!g2(failure, P)[error(ErrorId), error_msg(Msg)]
   <- .intention(Id, State, Stack, current);
      .print(State);
      .print(Stack);
      !show(Stack).
+!show([]) <- .stopMAS.
+!show([im(Label, Trigger, Body, Unifier) | Rest]) <- .print(Trigger, " ", Unifier); !show(Rest).
