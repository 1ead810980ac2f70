// The agent of the thesis' counter example (Chapter 2, section 4.2). Two additions: it tells the
// creator when it observes the counter, and it stops the system after the third increment.
!observe.

+!observe : true <- ?myTool(C); // discover the tool
    focus(C);
    .send(counter_creator, tell, ready).

+count(V) <- println("observed new value: ", V);
    if (V >= 3) { .stopMAS }.

+tick[artifact_name(Id, "c0")] <- println("perceived a tick").

+?myTool(CounterId) : true <- lookupArtifact("c0", CounterId).

-?myTool(CounterId) : true <- .wait(10); ?myTool(CounterId).
