// The agent of the thesis' counter example (Chapter 2, section 4.2), unchanged but for the end.
!observe.

+!observe : true <- ?myTool(C); // discover the tool
    focus(C).

+count(V) <- println("observed new value: ", V);
    if (V >= 3) { .stopMAS }.

+tick[artifact_name(Id, "c0")] <- println("perceived a tick").

+?myTool(CounterId) : true <- lookupArtifact("c0", CounterId).

-?myTool(CounterId) : true <- .wait(10); ?myTool(CounterId).
