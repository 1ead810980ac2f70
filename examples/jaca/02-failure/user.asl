!use.
+!use <- makeArtifact("t0", "demo.CappedTally", [40], T); !push(T).
+!push(T) <- for (.range(I, 1, 100)) { inc [artifact_id(T)] }.
-!push(T) [error_msg(Msg), env_failure_reason(inc_failed("cap_reached", Last))]
    <- println(Msg); println("last value is ", Last); .stopMAS.
