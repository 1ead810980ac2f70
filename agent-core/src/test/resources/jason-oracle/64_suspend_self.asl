// An intention suspends itself; another resumes it.
!a. !b.
+!a <- .print(a1); .suspend; .print(a2).
+!b <- .print(b1); .print(b2); .resume(a); .print(b3); .print(b4); .stopMAS.
