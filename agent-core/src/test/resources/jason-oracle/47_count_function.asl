// .count and .length as arithmetic functions; math functions in contexts.
b(1). b(2). b(3).
!start.
+!start : .count(b(_)) > 2 <- X = .count(b(_)) * 10; L = .length([a, b]) + .length("xyz"); .print(X, " ", L); .stopMAS.
+!start <- .print(wrong); .stopMAS.
