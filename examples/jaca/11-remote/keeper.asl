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
     !visitor_gone;
     println("the visitor left");
     .stopMAS.

// a joined agent has a body artifact in the workspace until it quits
+!visitor_gone <- lookupArtifact("body_voyager", _); .wait(20); !visitor_gone.
-!visitor_gone.
