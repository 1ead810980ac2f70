// How the reader reacts to the meter it focuses (reader.asl makes the meter; in ext_thread.jcm
// the project makes it and the agent focuses it, as in JaCaMo's ext_thread).
@big [atomic]
+reading(V) : V >= 100 & not done <- +done; println("bumped to ", V); .stopMAS.
@bump [atomic]
+reading(V) : V >= 13 & not bumped <- +bumped; bump.
