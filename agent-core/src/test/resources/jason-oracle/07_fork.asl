// The fork operators: B1 |&| B2 runs both branches as intentions of their own and goes on when
// both have ended; B1 ||| B2 goes on with the first to end and drops the others.
!start.
+!start <- !a(2) |&| !b(3);
           .print(both_done);
           (!w(100, x) ||| !w(2000, y));
           .print(first_done);
           !w(1500, p) |&| (!w(4000, q) ||| (!w(100, r); !w(100, s)));
           .print(nested_done);
           .wait(4000);
           .print(end);
           .stopMAS.
+!a(0).
+!a(N) <- .print(a(N)); !a(N - 1).
+!b(0).
+!b(N) <- .print(b(N)); !b(N - 1).
+!w(T, L) <- .wait(T); .print(L).
