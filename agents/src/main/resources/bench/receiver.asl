+last[source(sender)] <- .stopMAS.
