!watch.

+!watch
  <- ?current_wsp(_, Name, Node);
     println("keeping ", Name, " (", Node, ")");
     ?tally(T);
     focus(T).

+?tally(T) <- lookupArtifact("tally", T).
-?tally(T) <- .wait(20); ?tally(T).

+count(2)
  <- println("the visitor counted to 2");
     .wait(1000);
     .stopMAS.
