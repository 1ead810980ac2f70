!send.
+!send <- makeArtifact("outbox", "demo.Mailbox", []); ?inbox(Inbox); focus(Inbox).
+?inbox(Id) <- lookupArtifact("inbox", Id).
-?inbox(Id) <- .wait(20); ?inbox(Id).
// the receiver's port, perceived by focusing its inbox
+port(P) [artifact_name(_, "inbox")] <- !send_all(P).
+!send_all(P) <- .concat("localhost:", P, To);
    send("hello1", To) [artifact_name("outbox")];
    .wait(200);   // the first message goes to receive, the others to the receiving loop
    send("hello2", To) [artifact_name("outbox")];
    send("hello3", To) [artifact_name("outbox")].
