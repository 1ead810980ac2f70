!open.
+!open <- makeArtifact("window", "demo.NumberWindow", [], W); focus(W);
          println("type a number and ENTER, press ok to add one, drag the mouse; close the window to stop").
-!open[error_msg(M)] <- println(M); .stopMAS.
+value(V) <- println("value is now ", V).
+ok : value(V) <- setValue(V + 1).
+dragged(X, Y) <- println("mouse dragged to ", X, ",", Y).
+closed <- println("window closed"); .stopMAS.
