// .get_src_info: the line where the literal was written, wherever it is asked.
b(p(1)).
c(d(2)).

!start.

+!start
   <- X = f(1);
      Y = g(X);
      .get_src_info(X, S1); .print(S1);
      .get_src_info(Y, S2); .print(S2);
      !show(h(X));
      ?b(V); .get_src_info(V, S3); .print(S3);
      ?b(W)[source(Z)];
      .findall(B, b(B), L); .print(L);
      ?c(D); .get_src_info(D, S4); .print(S4);
      +e(k(1)); .get_src_info(e(x), S8); .print(S8);
      ?e(K); .get_src_info(K, S5); .print(S5);
      .term2string(T, "m(1)"); .get_src_info(T, S6); .print(S6);
      .get_src_info(V, S7); .print(S7);
      .my_name(N); .send(N, tell, q(r(1))); .wait(100); ?q(R); .get_src_info(R, S9); .print(S9);
      .get_src_info(b(p(V)), S10); .print(S10);
      X2 =.. [f, [1], []]; .get_src_info(X2, S11); .print(S11);
      .stopMAS.

+!show(A)
   <- .get_src_info(A, S); .print(show(S));
      A = h(I); .get_src_info(I, S2); .print(show(S2)).
