+forks(L, R)[source(host)] <- !meals(3).
+!meals(0) <- .send(host, tell, full).
+!meals(N) : forks(L, R)
    <- .concat("fork", L, FL); .concat("fork", R, FR);
       acquireTicket; pick [artifact_name(FL)]; pick [artifact_name(FR)];
       .my_name(Me); println(Me, " eats with forks ", L, " and ", R);
       putDown [artifact_name(FL)]; putDown [artifact_name(FR)]; returnTicket;
       !meals(N - 1).
