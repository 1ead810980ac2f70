// the reading grows by itself (the meter's own thread); at 13 the agent bumps it by 100
!start.
+!start <- makeArtifact("meter", "tools.Meter", [10, 50], M); focus(M).
{ include("meter_reader.asl") }
