// Namespaced literals through internal actions and operators: .abolish, .count, .add_annot, =.., ==, .sort, .term2string.
ns3::b(1). ns3::b(2). ns3::c. b(3). ns4::b(4).
!s.
+!s <- .abolish(ns3::_); .findall(N::X, N::b(X), L); .print(L);


       .count(ns4::b(_), C); .print(C);
       .add_annot(ns4::b(4), a, ns4::R); .print(R);
       ns4::b(4)[x] =.. LL; .print(LL);
       Z =.. [default, k, [1], [a]]; .print(Z);
       if (ns4::b(4) == ns4::b(4) & ns4::b(4) \== b(4)) { .print(eq) };
       .sort([z::a, b, a::c, y::a, a], S); .print(S);
       .term2string(ns7::T, "ns7::q(1)"); .print(T);
       .term2string(ns8::q(2), Str); .print(Str);
       .stopMAS.
+!ns5::g(X) <- .print(X).
+!N::g(X) <- .print(X).
