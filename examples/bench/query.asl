// 5 000 facts, then 200 turns of .findall, .count and a test goal over them.
!go.
+!go <- for (.range(I, 1, 5000)) { +item(I, I mod 7) }; .print(start); !q(0).
+!q(200) <- .print(end); .stopMAS.
+!q(N) <- .findall(I, item(I, 3), L); .count(item(_, 5), C); ?item(N + 1, K); !q(N + 1).
