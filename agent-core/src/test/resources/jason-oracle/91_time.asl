!g.
+!g <- .time(H, M, S); if (H >= 0 & H < 24 & M >= 0 & M < 60 & S >= 0 & S < 60) { .print(ok) }; .time(H2, M2, S2, MS); if (MS >= 0 & MS < 1000) { .print(ms_ok) }; .stopMAS.
