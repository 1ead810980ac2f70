// Annotated variables with a tail, V[H|T]: the annotations not matched go to the tail, on
// either side of the unification (Jason's subset rule for annotations).
!t.
+!t <- L = a[test,atomic]; L = N[H|T]; .print(N, " ", H, " ", T);
   M = b[x]; N2[Y|Z] = M; .print(N2, " ", Y, " ", Z);
   for (.member(K, [a[test,y], b[x,test], c[x]]) & K = _[test|R]) { .print(K, " ", R) };
   if (p[c,a,b] = P[a|Rest]) { .print(P, " ", Rest) };
   .stopMAS.
