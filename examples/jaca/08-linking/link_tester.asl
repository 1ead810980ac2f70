!test.
+!test
    <- makeArtifact("dispatcher", "demo.Dispatcher", [], D);
       makeArtifact("acc", "demo.Accumulator", [], A);
       linkArtifacts(D, "sink", A);
       println("linked");
       forward; forward;
       readBack(V); println("total through the port: ", V);
       spawnAndUse(W); println("total of its own accumulator: ", W);
       !call_link_directly.
+!call_link_directly <- add(1) [artifact_name("acc")].
-!call_link_directly [env_failure_reason(R)] <- println("an agent cannot call a link operation: ", R); .stopMAS.
