package jacabot.app.sweep;

import jacabot.robot.Experiment;

/**
 * One run of a sweep, as the CSV holds it: which run, how it ended, its figures and the verdict.
 *
 * @param status     {@code ok}, {@code crash}, {@code hang} (wall-time bound reached), {@code early-end} or
 *                   {@code agent-failure} (the agent failed at its job: {@link jacabot.app.run.FailureWatch})
 * @param simulated  simulated seconds the run covered
 * @param wall       wall-clock seconds it took
 * @param reason     why it failed ("" on success): the status' message, then the criteria's reasons
 */
public record RunOutcome(Experiment experiment, String world, String controller, long seed, String status, boolean success,
                         String reason, double simulated, double wall, SuccessCriteria.Figures figures, double batteryMin,
                         int lost) {
    public static final String OK = "ok", CRASH = "crash", HANG = "hang", EARLY_END = "early-end",
            AGENT_FAILURE = "agent-failure";
}
