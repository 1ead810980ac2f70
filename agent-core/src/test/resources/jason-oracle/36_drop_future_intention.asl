// .drop_future_intention(G): drops the intentions whose top plan has !G or !!G in its body as
// written (variables unbound), the calling intention included.
!start.

+!start
   <- !!worker(1); !!worker(2); !!other;
      .wait(100);
      !drop(step(1)); .print(after_drop);
      !!self_case;
      .wait(1200);
      .print(end); .stopMAS.

+!drop(G) <- .drop_future_intention(G); .print(dropped(G)).

+!worker(N) <- .print(w(N)); .wait(700); !step(N); .print(w_end(N)).
+!other <- .print(o); .wait(700); !step(3); .print(o_end).
+!step(N) <- .print(step(N)).

// the calling intention's own plan posts !z: it is dropped with it
+!self_case <- .print(self1); .drop_future_intention(z); .print(self2); !z.
+!z <- .print(z).
