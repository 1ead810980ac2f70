!use_java.

+!use_java
  <- cartago.new_obj("demo.Tally", [5], T);
     cartago.invoke_obj(T, add);
     cartago.invoke_obj(T, add(3));
     cartago.invoke_obj(T, total, N);
     println("total: ", N);
     cartago.invoke_obj("java.lang.Math", max(4, 9), M);
     println("max: ", M);
     cartago.invoke_obj("java.lang.System", currentTimeMillis, Now);
     if (Now > 0) { println("the clock runs") };
     cartago.invoke_obj("java.lang.Class", forName("demo.Tally"), C);
     println("class: ", C);
     cartago.new_array("int", [3, 1, 2], A);
     cartago.invoke_obj("java.util.Arrays", sort(A));
     cartago.array_to_list(A, L);
     println("sorted: ", L);
     !bad_call(T);
     !missing_method(T);
     .stopMAS.

+!bad_call(T) <- cartago.invoke_obj(T, reset(-1)).
-!bad_call(T)[error(E), error_msg(Msg)] <- println(E, ": ", Msg).

+!missing_method(T) <- cartago.invoke_obj(T, multiply(2)).
-!missing_method(T)[error(E), error_msg(Msg)] <- println(E, ": ", Msg).
