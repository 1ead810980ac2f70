!g.
+!g <- .remove_plan(p1); .relevant_plans({+!t}, _, L); .length(L, N); .print(N); !t;
       .add_plan({@p3 +!t <- .print(three)}, self, begin); !t; .remove_plan(p3, self); !t; .stopMAS.
@p1 +!t <- .print(one).
@p2 +!t <- .print(two).
