// Variables bound inside a while loop and an if are visible after them or not, as in Jason.
n(0).
!start.
+!start <-
    while (n(N) & N < 2) { -+n(N + 1); Z = N };
    if (n(K)) { W = K };
    .print(W);
    if (.ground(Z)) { .print("Z bound") } else { .print("Z free") };
    for (.member(M, [1, 2])) { Q = M };
    if (.ground(Q)) { .print("Q bound") } else { .print("Q free") };
    .stopMAS.
