// A small agent of the debugger's tests (obstacle avoidance's middleware): labels of its own.
!start.

@begin +!start <- lookupArtifact("middleware", Id); focus(Id); accept; !waitConnection.

@connected +!waitConnection : connected(true) <- acquireData; setSpeeds(120, 120); .wait(1500); !drive(1).
@notYet +!waitConnection <- .wait(100); !waitConnection.

@drive +!drive(N) <- .wait(700); setSpeeds(120, 100 + N * 5 mod 40); !drive(N + 1).

@turnAway +obstacle(true) <- setSpeeds(-100, 100).
