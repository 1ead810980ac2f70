// { register_function("f", N, "p") } makes f(A1..AN) the last argument of p(A1..AN, R) (evaluated
// once the arguments are bound, also inside rules and .findall); .set.* keep a sorted set and
// .queue.* a queue (by the standard order with priority), both usable by .member.
{ register_function("my.h", 2, "h") }
h(State, Goal, H) :- H = math.abs(Goal - State).
r(X, F) :- F = my.h(X, 9) + 1.
q(L) :- .findall(F, (.member(X, [1, 2]) & F = my.h(X, 9) + 1), L).
!t.
+!t <- X = my.h(3, 9); .print(X); Y = my.h(3, 9) + 2; .print(Y);
   ?r(3, F); .print(F); ?q(L); .print(L);
   .queue.create(Q, priority); .queue.add_all(Q, [s(8, 1, a), s(10, 2, b), s(9, 1, c), s(8, 0, d)]);
   .queue.add(Q, s(7, 5, e));
   .queue.remove(Q, A); .queue.remove(Q, B); .queue.head(Q, C); .print(A, B, C);
   .queue.create(P); .queue.add_all(P, [z, y]); .queue.add(P, x); .queue.remove(P, P1); .print(P1);
   .findall(E, .member(E, P), PL); .print(PL);
   .set.add_all(S, [c, a, b]); .set.add(S, a); .set.add(S, f(1));
   if (.member(b, S)) { .print(member) };
   .findall(Z, .member(Z, S), SL); .print(SL);
   T0 = system.time; if (T0 > 0) { .print(time_ok) };
   .stopMAS.
