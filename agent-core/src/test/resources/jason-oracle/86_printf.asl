!g.
+!g <- .printf("%s items", 3); .printf("%s and %s", a, "b"); .printf("%5.2f|", 3.14159); .printf("plain"); .stopMAS.
