// Messages with namespaced contents (sent to oneself): tell, untell, achieve, asks answered by
// the belief base and by a +? plan; NS::X variables take the namespace apart.
!start.
+!start
   <- .my_name(Me);
      .send(Me, tell, ns1::v(1));
      .send(Me, tell, v(2));
      .send(Me, achieve, ns2::go(3));
      .wait(200);
      .send(Me, askOne, ns1::v(X), ns1::v(X)[source(Q)]); .print(X, " ", Q);
      .send(Me, askAll, ns1::v(Y), A2); .print(A2);
      .send(Me, askOne, v(Z), A3); .print(A3);
      .send(Me, untell, ns1::v(1));
      .wait(200);
      .send(Me, askOne, ns1::v(_), A4); .print(A4);
      .send(Me, askOne, ns3::w(K), NS::W); .print(NS, " ", W, " ", K);
      ns1::a(1) = N1::B1; .print(N1, " ", B1);
      if (not (ns1::a(1) = ns2::B2)) { .print(other_ns) };
      .findall(N::C, N::v(C), L); .print(L);
      .stopMAS.
+N::v(X)[source(S)] : S \== self <- .print(got(N, X)).
-ns1::v(X)[source(S)] <- .print(lost(X)).
+!ns2::go(X)[source(S)] <- .print(go(X)).
+?ns3::w(7).
