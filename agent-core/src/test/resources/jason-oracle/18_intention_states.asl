// .intention's state of a waiting intention tells why it waits, as Jason's: waiting[reason(...)].
!w1.
!w2.
!w3.
!look.
+!w1 <- .wait(300).
+!w2 <- .wait({+go}).
+!w3 <- .wait(ready, 400).
+!look
   <- .wait(100);
      for (.intention(I, S, [im(_, {+!G}, _, _)|_]) & G \== look) {
          .print(I, " ", G, " ", S);
      };
      .stopMAS.
