package jacabot.app.scenario;

import jacabot.robot.run.RunSummary;
import java.util.List;
import java.util.Optional;

/**
 * What a {@link Scenario} run leaves: the run's summary (picks, deliveries, battery, contacts,
 * coverage, ...), its event log, the agents' console lines, and why the agent failed at its job
 * when it did (the run then ended at that step: {@link jacabot.app.run.FailureWatch}).
 */
public record ScenarioResult(RunSummary summary, List<String> console, Optional<String> agentFailure) {
    public ScenarioResult {
        console = List.copyOf(console);
    }

    /** {@return the event log, one {@code t=SECONDS what} line per event (as event-log.txt)} */
    public String eventLog() {
        return summary.eventLog();
    }

    /** {@return the events as lines} */
    public List<String> events() {
        return summary.events();
    }

    /** {@return the console lines containing {@code text}} */
    public List<String> consoleLines(String text) {
        return console.stream().filter(l -> l.contains(text)).toList();
    }
}
