// 100 000 subgoals, each with 30 candidate plans whose contexts start with a comparison.
v(0, 0). v(1, 0). v(2, 0). v(3, 0). v(4, 0). v(5, 0). v(6, 0). v(7, 0). v(8, 0). v(9, 0). v(10, 0). v(11, 0). v(12, 0). v(13, 0). v(14, 0). v(15, 0). v(16, 0). v(17, 0). v(18, 0). v(19, 0). v(20, 0). v(21, 0). v(22, 0). v(23, 0). v(24, 0). v(25, 0). v(26, 0). v(27, 0). v(28, 0). v(29, 0).
!go.
+!go <- .print(start); !step(0).
+!step(100000) <- .print(end); .stopMAS.
+!step(N) : N mod 30 == 0 & v(0, V) <- -v(0, V); +v(0, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 1 & v(1, V) <- -v(1, V); +v(1, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 2 & v(2, V) <- -v(2, V); +v(2, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 3 & v(3, V) <- -v(3, V); +v(3, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 4 & v(4, V) <- -v(4, V); +v(4, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 5 & v(5, V) <- -v(5, V); +v(5, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 6 & v(6, V) <- -v(6, V); +v(6, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 7 & v(7, V) <- -v(7, V); +v(7, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 8 & v(8, V) <- -v(8, V); +v(8, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 9 & v(9, V) <- -v(9, V); +v(9, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 10 & v(10, V) <- -v(10, V); +v(10, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 11 & v(11, V) <- -v(11, V); +v(11, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 12 & v(12, V) <- -v(12, V); +v(12, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 13 & v(13, V) <- -v(13, V); +v(13, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 14 & v(14, V) <- -v(14, V); +v(14, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 15 & v(15, V) <- -v(15, V); +v(15, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 16 & v(16, V) <- -v(16, V); +v(16, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 17 & v(17, V) <- -v(17, V); +v(17, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 18 & v(18, V) <- -v(18, V); +v(18, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 19 & v(19, V) <- -v(19, V); +v(19, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 20 & v(20, V) <- -v(20, V); +v(20, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 21 & v(21, V) <- -v(21, V); +v(21, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 22 & v(22, V) <- -v(22, V); +v(22, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 23 & v(23, V) <- -v(23, V); +v(23, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 24 & v(24, V) <- -v(24, V); +v(24, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 25 & v(25, V) <- -v(25, V); +v(25, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 26 & v(26, V) <- -v(26, V); +v(26, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 27 & v(27, V) <- -v(27, V); +v(27, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 28 & v(28, V) <- -v(28, V); +v(28, V + 1); !step(N + 1).
+!step(N) : N mod 30 == 29 & v(29, V) <- -v(29, V); +v(29, V + 1); !step(N + 1).
