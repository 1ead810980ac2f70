!consume.
+!consume <- ?queue_ready; !take.
+!take <- take(Item); .my_name(Me); println(Me, " consumed ", Item); consumed; !!take.
+?queue_ready <- lookupArtifact("queue", _).
-?queue_ready <- .wait(20); ?queue_ready.
