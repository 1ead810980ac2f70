// Skill: the energy agent of a robot shared with a task agent (not in the thesis: its Chapter 6
// wish, "the single robot programmed by more agents"). It watches the battery and commands the
// wheels only for the trip to the charger and back (recharge-trip.asl): on a low battery it asks
// the task agent to suspend (.send(T, achieve, suspend)) and waits for the wheels (acquireWheels,
// which the task agent releases once it has stopped); back at the marked point it restores the
// orientation, releases the wheels and asks the task agent to resume. It has no motion of its
// own: between recharges its wheel plans stand aside (wheelsNotMine).
// Reads: taskAgent(T), the task agent's name (the agent file's).
// Needs: shared-wheels.asl (first), recharge-trip.asl. Include it before initial-phase.asl (its
// +!moving comes first).

wheelsNotMine :- not charging.

@noMotionLoop +!moving : taskAgent(T) <- .print("Watching the battery; ", T, " has the wheels").

@suspendTaskAgent
+!suspendTask : taskAgent(T)
    <- .send(T, achieve, suspend); acquireWheels; .print("The wheels are mine: to the charger").
@resumeTaskAgent
+!resumeTask(O) : taskAgent(T)
    <- !restoreOrientation(O); -charging; releaseWheels; .send(T, achieve, resume).
