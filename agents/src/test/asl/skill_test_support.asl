// What the skill tests share (included by each *_test.asl; not a test file itself): percepts as
// the architecture adds and removes them, each in an intention of its own, and bounded waits.

@perceive +!perceive(B) <- +B.
@unperceive +!unperceive(B) <- -B.
// a percept that comes Ms milliseconds later (while the skill waits for it)
@perceiveAfter +!perceive_after(B, Ms) <- .wait(Ms); +B.

// a new test starts with no operation recorded
@forgetCalls +!forget_calls <- .abolish(mock_called(_)).

// waits (polling, at most T ms) until the condition holds; the assertion after it says if it did not
@untilHolds +!until(C, _) : C.
@untilPoll +!until(C, T) : T > 0 <- .wait(20); !until(C, T - 20).
@untilTimedOut +!until(_, _).
