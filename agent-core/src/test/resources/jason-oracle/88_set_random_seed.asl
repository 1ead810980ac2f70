!g.
+!g <- .set_random_seed(42); .random(A); .set_random_seed(42); .random(B);
       if (A == B) { .print(same) } else { .print(different) };
       .random(R); if (R >= 0 & R < 1) { .print(in_range) }; .stopMAS.
