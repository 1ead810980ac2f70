!s.
+!s <- .stopMAS.
