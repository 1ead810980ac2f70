!check.
+!check <- makeArtifact("r0", "demo.Refuser"); attempt [artifact_name("r0")]; println("not reached").
-!check [error_msg(Msg), env_failure_reason(refusal(A, B))] <- println("failure: ", Msg, " ", A, " ", B); .stopMAS.
