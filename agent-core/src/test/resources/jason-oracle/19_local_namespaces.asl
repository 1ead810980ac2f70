// Local namespaces print with their unique names; a forward declaration makes a later block local.
{ namespace(priv, local) }
{ begin namespace(priv) }
secret(1).
+!work(N) : not .intend(::work(_)[source(outer)]) <- .print(working(N, this_ns)); ?secret(S); .print(S).
{ end }
!start.
+!start <- .findall(X, priv::secret(X), L); .print(L);
           .relevant_plans({+!priv::work(_)}, P); .length(P, NP); .print(NP);
           !priv::work(7);
           ?priv::secret(Y); .print(Y);
           .print(priv::secret(Y));
           if (not priv::secret(2)) { .print(no) };
           .stopMAS.
