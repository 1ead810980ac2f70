// Logical formulas as plan body steps: Jason sends `not b`, `a & b` and `a | b` to the
// environment as actions (action_failed without one), while a relation is a constraint
b(1).
!s1.
+!s1 <- .print(a); not b(2).
-!s1[error(E),error_msg(M),code(C)] <- .print(a, " ", E, " ", M, " ", C); !s2.
+!s2 <- .print(b); b(1) & true.
-!s2[error(E),code(C)] <- .print(b, " ", E, " ", C); !s3.
+!s3 <- .print(c); (1 > 2 | 3 < 4).
-!s3[error(E),code(C)] <- .print(c, " ", E, " ", C); !s4.
+!s4 <- .print(d); 2 > 1; .print(d_ok); 1 > 2.
-!s4[error(E),code(C)] <- .print(d, " ", E, " ", C); !s5.
+!s5 <- .print(e); if (not b(2) & b(1)) { .print(in_if) }; X = 1; not (X == 2).
-!s5[error(E),code(C)] <- .print(e, " ", E, " ", C); .stopMAS.
