+last[source(sender)] <- .print(end); .stopMAS.
