// Skill: a larger charge reserve once the battery has been drained, not in the thesis. With a task that
// ends at a known time, a charge ends as soon as the battery less a reserve covers the time left
// (recharge-trip's chargeUntilLasts): no room for a sudden loss (a world's drain, a cell that fails).
// Tidy-up world 205 × 3: a drain of 172 J, a charge ended at 758 J, a drain of 284 J 24 s later and a
// second trip, the last cylinder stored at 591 s. The larger reserve on every charge (300 J instead of
// 100 J) kept every robot longer on the charger and lost a run a drain never touched (world 181 × 1);
// here it holds only once the battery has fallen by more than the wheels draw between two readings.
// Parameters:
chargeReserve(100).   // J over the time left's need at which a charge ends
drainReserve(300).    // J the same once a drain was seen (the generated worlds' drains: 100-300 J)
drainStep(50).        // J: a fall this large between two readings is a drain (the wheels draw 0.1 J a control step)
// Reads: battery(B) (the middleware's). Beliefs: drainSeen.
// Gives: chargeUntilLasts(R) (recharge-trip's). Include it with recharge.

chargeUntilLasts(R) :- drainSeen & drainReserve(R).
chargeUntilLasts(R) :- not drainSeen & chargeReserve(R).
// on the old reading's removal the new one is believed already; no plan runs but for a drain
@drainSeen -battery(B0) : not drainSeen & battery(B) & drainStep(S) & B0 - B > S <- +drainSeen.
