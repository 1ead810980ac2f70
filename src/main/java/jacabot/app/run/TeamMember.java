package jacabot.app.run;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.syntax.Literal;
import jacabot.cartago.ArtifactId;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.link.MiddlewareLink;
import jacabot.experiments.link.StepData;
import jacabot.robot.RobotController;
import jacabot.robot.link.Command;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * One robot of a {@link TeamLockstepRun}: its middleware artifact, its link to its controller (in
 * this process, or in the controllers' process), the step its link has delivered and not yet
 * answered, its agent's failure watch and its event log (its controller's lines, its agent side's).
 */
final class TeamMember {
    private final String robot;
    private final ArtifactId middlewareId;
    private final MiddlewareArtifact middleware;
    private final FailureWatch failures;
    private final List<Literal> goals;
    private final List<String> controllerLog = new ArrayList<>();
    private final List<String> agentLog = new ArrayList<>();
    private final TeamStepCollector collector;
    private MiddlewareLink link;
    /** Null when the controller is in another process. */
    private RobotController controller;
    private StepData delivered;
    private boolean reasoned;
    private String left;

    TeamMember(String robot, ArtifactId middlewareId, MiddlewareArtifact middleware, FailureWatch failures, List<Literal> goals,
            Runnable onArrival) {
        this.robot = robot;
        this.middlewareId = middlewareId;
        this.middleware = middleware;
        this.failures = failures;
        this.goals = goals;
        this.collector = new TeamStepCollector(onArrival);
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

    /** The controller's lines, in the order they came (on the simulation thread); empty when it is in another process. */
    List<String> controllerLog() {
        return controllerLog;
    }

    /** The agent side's lines: a step's readings and the commands answered, one a step. */
    List<String> agentLog() {
        return agentLog;
    }

    /** {@return the controller's lines, a line {@code --}, the agent side's (as {@link LockstepCoordinator.Result#eventLog})} */
    List<String> eventLog() {
        List<String> all = new ArrayList<>(controllerLog.size() + agentLog.size() + 1);
        all.addAll(controllerLog);
        all.add("--");
        all.addAll(agentLog);
        return all;
    }

    TeamStepCollector collector() {
        return collector;
    }

    /** {@return the robot's controller in this process, null when it is in another} */
    RobotController controller() {
        return controller;
    }

    MiddlewareLink link() {
        return link;
    }

    /** The controller in this process, joined through {@code l}. */
    void connect(InProcessLink l) {
        this.controller = l.controller();
        connect(l.middleware());
    }

    /** The middleware end of the robot's link; its controller may be in another process. */
    void connect(MiddlewareLink l) {
        this.link = l;
        l.handOver(collector);
    }

    /** {@return the step the link delivered since the last answer, null if none (or the agent has left)} */
    StepData takeStep() {
        delivered = left == null ? collector.take() : null;
        return delivered;
    }

    /** After the team's first reasoning: an agent with no plan for its initial goal has failed. */
    void firstReasoningDone(LocalMAS mas) {
        if (!reasoned && left == null) {
            reasoned = true;
            failures.firstReasoningDone(mas.agent(robot).planLibrary(), goals);
        }
    }

    /** Sends the agent's commands of this step and the step's acknowledgement to the controller, {@code tap} seeing them first. */
    void answer(boolean log, TeamLockstepRun.RobotStepListener tap) {
        StepData d = delivered;
        delivered = null;
        if (d == null || left != null) {
            return;
        }
        List<Command> commands = new ArrayList<>(middleware.takeCommands());
        if (log) {
            agentLog.add(LockstepCoordinator.describe(d.step(), d.simTimeMs(), d.readings(), commands));
        }
        tap.afterStep(robot, d, Collections.unmodifiableList(commands));
        link.answerStep(commands, d.step());
    }

    /** {@return why the robot's agent left the team, null while it is in} */
    String left() {
        return left;
    }

    /**
     * The robot's agent is gone: its step goes unanswered and its link is closed, so that its
     * controller's fail-safe stops the robot and its team stops waiting for it.
     */
    void agentLeft(String why) {
        left = why;
        delivered = null;
        if (link != null) {
            link.close();
        }
    }

    void closeLink() {
        if (controller != null) {
            controller.close();
        }
        if (link != null) {
            link.close();
        }
    }
}
