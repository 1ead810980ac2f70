!visit.

+!visit
  <- ?current_wsp(Home, _, _);
     +home(Home);
     !no_attic;
     joinRemoteWorkspace("main", "localhost", Remote);
     ?current_wsp(_, Name, _);
     println("hello from another process");
     println("joined ", Name, " remotely")[wsp_id(Home)];
     !use_tally;
     ?count(C);
     println("count is ", C)[wsp_id(Home)];
     quitWorkspace;
     ?current_wsp(_, Back, _);
     println("back in ", Back);
     .count(count(_), N);
     println("beliefs about the tally left: ", N);
     .stopMAS.

+!use_tally
  <- makeArtifact("tally", "demo.Tally", [], Id);
     focus(Id);
     bump;
     bump.

+!no_attic <- joinRemoteWorkspace("attic", "localhost", _).
-!no_attic[env_failure_reason(R), error_msg(M)]
  <- println("no attic there: ", R).
