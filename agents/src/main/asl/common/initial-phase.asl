// The initial phase shared by the four experiment agents (thesis Chapter 4 §5, "Common Aspects":
// "the procedure to create the artifact and put the focus on it ... we can call it, the initial phase").
// An agent includes it right after its +!start plan, so these plans keep the place they had in
// each agent's plan library (plan order and the p__N labels unchanged), and it supplies:
//   middlewarePort(P)      where the middleware it makes listens (the thesis: 4444);
//   middlewareClass(C)     the middleware artifact of its experiment;
//   +!start                !init(Id); focus(Id); accept; !waitConnection (its own console lines);
//   +!waitConnection       its set-up once connected(true), then acquireData; !moving, and the poll
//                          that waits for the connection (100 ms in §5, 500 ms in Appendix B).

// The experiment runner may have made the middleware already (lockstep runs); otherwise make it.
+!init(Id) <- lookupArtifact("middleware", Id).
-!init(Id) : middlewarePort(P) & middlewareClass(C)
    <- makeArtifact("middleware", C, [P], Id);
       println("Artifact created").
-!start[error_msg(M)] <- println("the robot cannot start: ", M); .stopMAS.
