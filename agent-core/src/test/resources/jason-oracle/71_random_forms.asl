// .random's forms with a seed (the agent's generator is java.util.Random, as Jason's), a plan
// with math.random in its body held in a variable is not evaluated by .intention, .list_files
// of a missing folder, and a test goal answered by a +? plan binding the caller's variables.
!t.
+!t <- .relevant_plans({+!r}, Plans);
       .set_random_seed(20); R = math.random(10); .intention(_, _, _, current);
       .random(X); .print(R, " ", X);
       .findall(Y, .random(Y, 3), L); .length(L, N); .print(N);
       .random([a, b, c], E); .print(E);
       .findall(F, .random([a, b, c], F, 4), L2); .print(L2);
       if (.random(Z, 0) & Z > 0.9) { .print(found) };
       .list_files("no/such/folder", Files); .print(Files);
       ?g(A, B); .print(A, " ", B);
       .stopMAS.
+!r <- S = math.random(5).
+?g(P, Q) <- P = 1; Q = f(P).
