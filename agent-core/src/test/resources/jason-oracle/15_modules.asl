// Modules: one file included into several namespaces (each with its own local namespace),
// at load time and with .include at run time.
{ include("ns_counter.asl", c1) }
{ include("ns_counter.asl", c2) }
!main.
+!main
   <- !c1::inc; !c1::inc; !c2::inc;
      ?c1::value(A); ?c2::value(B); .print(values(A, B));
      .include("ns_counter.asl", c3);
      !c3::inc; ?c3::total(C); .print(c3_total(C));
      .include("ns_counter.asl", NS);
      if (.atom(NS) & NS \== c3) { .print(new_namespace) };
      !NS::inc; ?NS::value(D); .print(d(D));
      .count(_::changed(_), K); .print(changed(K));
      .findall(X, c1::changed(X), L); .print(L);
      if (not state::count(_)) { .print(local_hidden) };
      .stopMAS.
+c1::changed(V) <- .print(c1_changed(V)).
+N::changed(V) : N \== c1 <- .print(other_changed(N, V)).
