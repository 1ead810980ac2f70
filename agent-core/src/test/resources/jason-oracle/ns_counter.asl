// A module (not a program of its own): included into a namespace by 15_modules.asl.
{ namespace(state, local) }
state::count(0).
value(V) :- state::count(V).
+!inc : state::count(N)
   <- -+state::count(N + 1);
      .print(inc_in(this_ns, N + 1));
      +::changed(N + 1).
+?total(T) <- ?value(T).
