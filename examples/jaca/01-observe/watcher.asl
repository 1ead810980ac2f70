!watch.
+!watch <- ?tally(T); focus(T); .send(maker, tell, watching).
+?tally(T) <- lookupArtifact("c0", T).
-?tally(T) <- .wait(10); ?tally(T).
+count(N) <- println("observed count ", N).
+ticked [artifact_name(_, "c0")] <- println("perceived a tick"); !finish.
+!finish : count(2) <- .stopMAS.
+!finish.
