package jacabot.app.run;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.syntax.Literal;
import jacabot.cartago.ArtifactId;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.link.StepData;
import jacabot.robot.link.Command;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * One robot of a {@link TeamLockstepRun}: its middleware artifact, its link to its controller, the
 * step its link has delivered and not yet answered, its agent's failure watch and its event log.
 */
final class TeamMember {
    private final String robot;
    private final ArtifactId middlewareId;
    private final MiddlewareArtifact middleware;
    private final FailureWatch failures;
    private final List<Literal> goals;
    private final List<String> eventLog = new ArrayList<>();
    private final TeamLockstepRun.StepCollector collector = new TeamLockstepRun.StepCollector();
    private InProcessLink link;
    private StepData delivered;
    private boolean reasoned;

    TeamMember(String robot, ArtifactId middlewareId, MiddlewareArtifact middleware, FailureWatch failures, List<Literal> goals) {
        this.robot = robot;
        this.middlewareId = middlewareId;
        this.middleware = middleware;
        this.failures = failures;
        this.goals = goals;
    }

    String robot() {
        return robot;
    }

    ArtifactId middlewareId() {
        return middlewareId;
    }

    FailureWatch failures() {
        return failures;
    }

    /** The controller's lines and the agent side's, in the order they came (both on the simulation thread). */
    List<String> eventLog() {
        return eventLog;
    }

    InProcessLink link() {
        return link;
    }

    void connect(InProcessLink l) {
        this.link = l;
        l.middleware().handOver(collector);
    }

    /** {@return the step the link delivered since the last answer, null if none} */
    StepData takeStep() {
        delivered = collector.take();
        return delivered;
    }

    /** After the team's first reasoning: an agent with no plan for its initial goal has failed. */
    void firstReasoningDone(LocalMAS mas) {
        if (!reasoned) {
            reasoned = true;
            failures.firstReasoningDone(mas.agent(robot).planLibrary(), goals);
        }
    }

    /** Sends the agent's commands of this step and the step's acknowledgement to the controller, {@code tap} seeing them first. */
    void answer(boolean log, TeamLockstepRun.RobotStepListener tap) {
        StepData d = delivered;
        delivered = null;
        if (d == null) {
            return;
        }
        List<Command> commands = new ArrayList<>(middleware.takeCommands());
        if (log) {
            eventLog.add(LockstepCoordinator.describe(d.step(), d.simTimeMs(), d.readings(), commands));
        }
        tap.afterStep(robot, d, Collections.unmodifiableList(commands));
        link.middleware().answerStep(commands, d.step());
    }

    void closeLink() {
        if (link != null) {
            link.close();
        }
    }
}
