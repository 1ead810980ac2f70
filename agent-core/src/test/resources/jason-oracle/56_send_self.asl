// Messages to oneself: tell and achieve carry source(self).
!start.
+!start <- .my_name(Me); .send(Me, tell, hello(1)); .send(Me, achieve, greet); .wait(done); .print(end); .stopMAS.
+hello(X)[source(S)] <- .print("hello ", X, " from ", S).
+!greet[source(S)] <- .print("greet from ", S); +done.
