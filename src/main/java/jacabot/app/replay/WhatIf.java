package jacabot.app.replay;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.PlanLibrary;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Plan;
import jacabot.app.inspector.ConsoleRecorder;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;

/**
 * "What if": a new lockstep run that reproduces a recorded one up to an instant (same world, seed
 * and agent: byte for byte the same steps) and then goes on with an edited agent, whose plans
 * replace the agent's plans there, as Jason's reload of an agent's plans does: beliefs, goals and
 * running intentions stay; the plans chosen from then on are the edited program's.
 */
public final class WhatIf {
    /** What the what-if run wrote, and when the plans were swapped (simulated ms, -1: never reached). */
    public record Result(String eventLog, long swappedAtMs, RunRecorder recorder) {
    }

    /** Why a real-time run starts no what-if. */
    public static final String REAL_TIME_REFUSAL = "a what-if needs a lockstep run's step log (a real-time run cannot be "
            + "made again step for step): run the experiment with --headless (lockstep) and start the what-if from that run";

    private WhatIf() {
    }

    /**
     * Runs the what-if.
     *
     * @param original the recorded run's agent
     * @param edited the agent whose plans take over after the step at {@code atMs}
     * @param outDir where its step log goes
     */
    public static Result run(SimWorld world, Experiment experiment, long seed, AgentSource original, AgentSource edited,
            long atMs, double seconds, Path outDir, PrintStream console) throws Exception {
        AgentProgram program = parseEdited(edited);
        Files.createDirectories(outDir);
        // its console by simulated time, as a lockstep experiment's: the inspector's console panel reads it
        ConsoleRecorder consoleFile = ConsoleRecorder.open(outDir, world::timeMs);
        var run = new LockstepRun(world, null, experiment, original, seed, consoleFile.tee(console));
        var recorder = RunRecorder.attach(world, world.robots().get(0).name());
        long[] swapped = {-1};
        try (consoleFile; RunTap tap = RunTap.attach(run, null, outDir, experiment, original.name() + " then " + edited.name())) {
            run.onStep(data -> { // on the run's thread, the agent idle: its plans can change
                if (swapped[0] < 0 && data.simTimeMs() >= atMs) {
                    swapPlans(run.mas().agent("robot"), program);
                    swapped[0] = data.simTimeMs();
                    consoleFile.line(data.simTimeMs(), "what-if: the edited agent's plans from here on");
                }
                consoleFile.events(recorder.events());
            });
            String log = run.runFor(seconds).eventLog();
            consoleFile.events(recorder.events());
            return new Result(log, swapped[0], recorder);
        }
    }

    /** Replaces the agent's own plans by the program's (the communication plans every agent has stay). */
    /**
     * {@return an edited agent's program, its includes read from where the run's agent came from}
     *
     * @throws IllegalArgumentException when it does not parse (its file:line:col): nothing is to change
     */
    static AgentProgram parseEdited(AgentSource edited) {
        try {
            return edited.parse(edited.parser());
        } catch (AslSyntaxException e) {
            throw new IllegalArgumentException(e.getMessage());
        }
    }

    static void swapPlans(Agent agent, AgentProgram program) {
        PlanLibrary library = agent.planLibrary();
        for (Plan p : new ArrayList<>(library.plans())) {
            if (!library.isKqmlPlan(p)) {
                library.remove(p.label().functor());
            }
        }
        for (Plan p : program.plans()) {
            library.add(p, false);
        }
    }

    /**
     * {@return the recorded run's agent: its file when it exists, else the experiment's packaged agent when the log names it}
     * @throws IOException when neither is there
     */
    public static AgentSource originalAgent(StepLog.Header header, Experiment experiment) throws IOException {
        Path file = Path.of(header.agentFile());
        if (Files.isRegularFile(file)) {
            return AgentSource.file(file);
        }
        // `jacabot experiment` names its packaged agent by its place in the repository
        if (header.agentFile().equals("agents/src/main/asl/" + experiment.id() + ".asl")) {
            return AgentSource.packaged(experiment, header.agentFile());
        }
        throw new IOException("the recorded run's agent '" + header.agentFile() + "' is not here (run from the folder "
                + "the run was started in)");
    }
}
