// Namespaces written as prefixes: ns::b and b are different beliefs, .namespace lists them.
!t.
+!t <- +b(1); +family::b(2); +family::brother(bob); +work::b(3);
       .findall(X, b(X), L0); .print(L0);
       .findall(X, family::b(X), L1); .print(L1);
       ?family::brother(B); .print(B);
       if (.namespace(family)) { .print(family_known) };
       if (not .namespace(other)) { .print(other_unknown) };
       -family::b(2); .findall(X, family::b(X), L2); .print(L2);
       .stopMAS.
+family::brother(X) <- .print(new_brother(X)).
