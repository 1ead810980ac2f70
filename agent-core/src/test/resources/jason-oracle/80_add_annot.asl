!g.
+!g <- .add_annot(b(1), x, B1); .print(B1);
       .add_annot(b(1)[y], x(2), B2); .print(B2);
       .add_annot([a, c(1), d[z]], s, L); .print(L);
       .add_annot(b(X), X, B3); X = k; .print(B3);
       .stopMAS.
