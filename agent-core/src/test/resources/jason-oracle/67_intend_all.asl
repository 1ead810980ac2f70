// .intend enumerates the goals of the intentions; .findall over it.
!job(1). !job(2). !show.
+!job(N) <- .wait({+never}).
+!show <- .wait(5); .findall(N, .intend(job(N)), L); .print(L); .count(.intend(_), C); .print(C); .stopMAS.
