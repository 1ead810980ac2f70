// .drop_desire of a posted !!goal before it is selected; .desire on events.
!start.
+!start <- !!late; if (.desire(late)) { .print("desired") }; .drop_desire(late); if (.desire(late)) { .print(still) } else { .print(dropped) }; .print(end); .stopMAS.
+!late <- .print("not printed").
