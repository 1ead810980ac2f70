ticks(0).
!watch.
+!watch <- ?tally(T); focus(T); .send(maker, tell, watching).
+?tally(T) <- lookupArtifact("c0", T).
-?tally(T) <- .wait(10); ?tally(T).
+count(N) <- println("observed count ", N); +seen(N); !finish.
@tick [atomic]
+ticked [artifact_name(_, "c0")] : ticks(K) <- println("perceived a tick"); -+ticks(K + 1); !finish.
// the run ends when both increments were seen and both signals perceived
+!finish : ticks(2) & seen(1) & seen(2) <- .stopMAS.
+!finish.
