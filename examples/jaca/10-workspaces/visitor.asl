!tour.

+!tour
  <- ?current_wsp(Home, HomeName, _);
     println("starting in ", HomeName);
     createWorkspace("kitchen");
     createWorkspace("garden");
     !join_missing;
     joinWorkspace("kitchen", Kitchen);
     ?current_wsp(_, N1, _);
     println("now in ", N1);
     makeArtifact("pot", "demo.Pot", [], Pot);
     out(note, "left in the kitchen");
     joinWorkspace("garden", _);
     ?current_wsp(_, N2, _);
     println("now in ", N2);
     out(note, "left in the garden");
     stir [artifact_id(Pot)];
     !no_pot_here;
     cartago.set_current_wsp(Kitchen);
     ?current_wsp(_, N3, _);
     println("back in ", N3);
     rd(note, Note);
     println("the note here: ", Note);
     focus(Pot);
     ?stirred(S);
     println("the pot was stirred ", S, " time(s)");
     quitWorkspace;
     ?current_wsp(_, N4, _);
     println("after quitting: ", N4);
     quitWorkspace;
     ?current_wsp(Home, N5, _);
     println("and finally in ", N5, " again");
     .findall(W, joinedWsp(_, W, _), Joined);
     println("joined: ", Joined);
     .stopMAS.

+!join_missing <- joinWorkspace("attic", _).
-!join_missing[env_failure_reason(R)] <- println("cannot join: ", R).

+!no_pot_here <- lookupArtifact("pot", _).
-!no_pot_here[env_failure_reason(R)] <- println("not here: ", R).
