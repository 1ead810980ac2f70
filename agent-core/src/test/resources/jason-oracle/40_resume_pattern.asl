// .resume(G) with a pattern: which suspended goals resume, and in which order.
!start.

+!start
   <- !!g(a, 1); !!g(b, 2); !!g(c, 3); !!g(d, 4);
      .wait(100);
      .print(first);
      .resume(g(_, _));
      .wait(100);
      .print(second);
      .resume(g(X, Y));
      .print(bound(X, Y));
      .wait(100);
      .print(all);
      .resume(g(_, _)); .resume(g(_, _)); .resume(g(_, _));
      .wait(100);
      .stopMAS.

+!g(X, N) <- .print(susp(X)); .suspend; .print(resumed(X)).
