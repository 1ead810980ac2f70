// 200 000 additions and deletions of a belief in a for loop.
!go.
+!go <- for (.range(I, 1, 200000)) { +v(I); -v(I) }; .stopMAS.
