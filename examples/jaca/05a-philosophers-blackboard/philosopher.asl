!sit.
+!sit <- .my_name(Me); .term2string(Me, MyName); in("seat", MyName, Left, Right);
    +forks(Left, Right); !meals(3).
+!meals(0) <- .my_name(Me); .term2string(Me, MyName); out("full", MyName).
+!meals(N) : forks(L, R)
    <- in("ticket"); in("fork", L); in("fork", R);
       .my_name(Me); println(Me, " eats with forks ", L, " and ", R);
       out("fork", L); out("fork", R); out("ticket");
       !meals(N - 1).
