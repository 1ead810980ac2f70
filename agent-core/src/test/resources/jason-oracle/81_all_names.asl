!g.
+!g <- .all_names(L); .print(L); .my_name(M); if (.member(M, L)) { .print(member) }; .stopMAS.
