!setup.
+!setup <- makeArtifact("c0", "demo.Tally", [], _).
// the watcher says when it watches: then the two increments are all seen
+watching[source(watcher)] <- inc; inc [artifact_name("c0")].
