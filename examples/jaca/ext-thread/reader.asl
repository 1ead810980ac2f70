// the reading grows by itself (the meter's own thread); at 13 the agent bumps it by 100
!start.
+!start <- makeArtifact("meter", "tools.Meter", [10, 50], M); focus(M).
@big [atomic]
+reading(V) : V >= 100 & not done <- +done; println("bumped to ", V); .stopMAS.
@bump [atomic]
+reading(V) : V >= 13 & not bumped <- +bumped; bump.
