ticks(0).
!use_clock.
+!use_clock <- makeArtifact("ticker", "demo.Ticker", [50], T); focus(T); println("clock starting"); start.
@count [atomic]
+tick : ticks(N) & N < 10 <- -+ticks(N + 1); println("tick ", N + 1); !check.
+tick.
+!check : ticks(10) <- stop; println("clock stopped"); .stopMAS.
+!check.
