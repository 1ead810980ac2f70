// Nested if/elif/else, and for with several conditions.
!start.
+!start <- for (.range(I, 0, 5)) { !c(I) }; .stopMAS.
+!c(I) <- if (I mod 2 == 0) { if (I > 2) { .print(I, " big even") } else { .print(I, " small even") } }
          elif (I == 3) { .print(I, " three") }
          else { .print(I, " odd") }.
