package jacabot.app.cli;

import jacabot.app.run.AgentSource;
import jacabot.app.run.RobotAgent;
import jacabot.experiments.WheelLease;
import jacabot.robot.Experiment;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/** {@code jacabot experiment NAME --agents A,B}: the robot programmed by several agents (the thesis' Chapter 6 wish). */
final class RobotAgents {
    private RobotAgents() {
    }

    /**
     * {@return the packaged agents {@code EXPERIMENT-NAME.asl}, each named NAME}
     * @param conflict the option given with {@code --agents} that names another agent, or null
     * @throws UserError for a conflicting option, a bad or repeated name, or an agent not packaged
     */
    static List<RobotAgent> packaged(Experiment experiment, List<String> names, String conflict) {
        if (conflict != null) {
            throw new UserError("--agents: not with " + conflict + " (--agents names the robot's agents)");
        }
        if (names.stream().allMatch(String::isBlank)) {
            throw new UserError("--agents: no agent named (suspend-resume has task and energy: --agents task,energy)");
        }
        var out = new ArrayList<RobotAgent>();
        for (String name : names) {
            if (!name.matches("[a-z][A-Za-z0-9_]*") || out.stream().anyMatch(a -> a.name().equals(name))) {
                throw new UserError("--agents: '" + name + "' must be a new agent name (a lower-case letter, then letters, digits, _)");
            }
            String file = experiment.id() + "-" + name + ".asl";
            try {
                out.add(new RobotAgent(name, AgentSource.resource("/asl/" + file, "agents/src/main/asl/" + file)));
            } catch (UncheckedIOException e) {
                throw new UserError("--agents: no packaged agent agents/src/main/asl/" + file
                        + " (suspend-resume has task and energy: --agents task,energy)");
            }
        }
        return out;
    }

    /** {@return one line: the control steps each agent drove the wheels in, steps with two drivers, refusals} */
    static String wheelSummary(WheelLease wheels) {
        String steps = wheels.stepsDriven().entrySet().stream().map(e -> e.getKey() + " " + e.getValue())
                .collect(Collectors.joining(", "));
        return "Wheels: control steps driven by " + (steps.isEmpty() ? "nobody" : steps) + "; steps with two drivers "
                + wheels.stepsWithTwoDrivers() + "; wheel commands refused " + wheels.refusals() + ".";
    }
}
