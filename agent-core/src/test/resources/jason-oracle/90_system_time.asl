!g.
+!g <- T1 = system.time; .wait(30); T2 = system.time; if (T2 - T1 >= 30 & T1 > 1600000000000) { .print(ok) } else { .print(T1, T2) }; .stopMAS.
