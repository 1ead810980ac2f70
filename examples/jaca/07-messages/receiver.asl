got(0).
!receive.
+!receive <- makeArtifact("inbox", "demo.Mailbox", [], Id);
    receive(Text, From); println("received ", Text); !count;
    focus(Id); startReceiving.
@msg [atomic]
+new_msg(Text, From) <- println("received ", Text); !count.
@count [atomic]
+!count : got(N) <- -+got(N + 1); !maybe_end(N + 1).
+!maybe_end(3) <- .stopMAS.
+!maybe_end(_).
