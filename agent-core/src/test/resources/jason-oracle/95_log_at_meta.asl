!g.
+!g <- .log(info, "shown ", 1); .log(fine, "hidden"); .log(severe, "also ", shown);
       .at("now +100 ms", {+!later}); !sub(2); .print(after_sub).
+!sub(X) <- .print(sub, X).
^!sub(X)[state(achieved)] <- .print(achieved, X).
+!later <- .print(later); .stopMAS.
