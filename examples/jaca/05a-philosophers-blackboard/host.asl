// lays the table: 5 forks, 4 tickets, each philosopher's forks; waits for 5 "full" tuples
!lay_table.
+!lay_table
    <- for (.range(I, 0, 4)) { out("fork", I) };
       for (.range(I, 1, 4)) { out("ticket") };
       for (.range(I, 1, 5)) { .concat("philosopher", I, Name); out("seat", Name, I - 1, I mod 5) };
       for (.range(I, 1, 5)) { in("full", P); println(P, " is full") };
       println("all philosophers ate"); .stopMAS.
