// Namespaces as Jason's modules: blocks, local names, ::b, this_ns, variables as namespaces.
{ begin namespace(inv, global) }
stock(apple, 3).
stock(pear, 0).
+!check(F) : stock(F, N) & N > 0 <- .print(have(F, N)).
+!check(F) <- .print(none(F)).
{ end }

{ begin namespace(sec, local) }
code(42).
{ end }

b(0).
ns2::b(2).
!main.

+!main
   <- !inv::check(apple);
      !inv::check(pear);
      ?sec::code(C); .print(code(C));
      .findall(N::b(X), N::b(X), L); .print(L);
      .findall(N, .namespace(N), NL); .print(NL);
      +ns3::c(1)[note];
      ?ns3::c(V)[note]; .print(c(V));
      if (not (Y = ns2::b(2))) { .print(var_takes_no_ns) };
      if (ns2::b(2) = N2::b(Z)) { .print(ns_var(N2, Z)) };
      if (.namespace(kqml)) { .print(kqml_ns) };
      ns2::b(2) =.. Parts; .print(Parts);
      if (not (T =.. [ns4, d, [1], []])) { .print(univ_ns_fails) };
      .print(this_ns, " ", default::b(0), " ", inv::stock(apple,3));
      !!ns2::g(1);
      .wait(100);
      .stopMAS.

+!N::g(A) <- .print(goal_in(N, A)).
+ns3::c(X)[source(S)] <- .print(added(X, S)).
