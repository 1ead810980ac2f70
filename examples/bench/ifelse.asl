// 100 000 turns of a for with if / elif / else, belief changes and arithmetic.
!go.
+!go <- .print(start); X = 0; for (.range(I, 1, 100000)) { if (I mod 3 == 0) { +m3(I) ; -m3(I) } elif (I mod 3 == 1) { Y = I * 2 } else { .length([I, I], L) } }; .print(end); .stopMAS.
