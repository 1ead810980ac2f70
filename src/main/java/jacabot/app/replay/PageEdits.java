package jacabot.app.replay;

import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.AgentProgram;
import jacabot.app.inspector.Debugger;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.RunEdits;
import jacabot.app.inspector.WhatIfJob;
import jacabot.app.run.AgentSource;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import java.io.BufferedReader;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.zip.GZIPInputStream;

/**
 * The inspector page's edits of a run's agent: a what-if from any instant (the run again from its
 * step log's header, the same world, seed and agent, then the edited plans; its history shown
 * beside the run's as another agent, with where the two first differ), and for a live lockstep
 * run halted by the debugger, the edited plans reloaded into the running agent.
 */
public final class PageEdits implements RunEdits {
    private final Inspector inspector;
    private final Path runDir;
    private final StepLog.Header header;
    private final Experiment experiment;
    private final AgentSource original;
    private final Callable<SimWorld> world;
    private final Agent live;
    private final Debugger debugger;
    private final AtomicInteger count = new AtomicInteger();

    private PageEdits(Inspector inspector, Path runDir, StepLog.Header header, Experiment experiment, AgentSource original,
            Callable<SimWorld> world, Agent live, Debugger debugger) {
        this.inspector = inspector;
        this.runDir = runDir;
        this.header = header;
        this.experiment = experiment;
        this.original = original;
        this.world = world;
        this.live = live;
        this.debugger = debugger;
    }

    /**
     * Edits of a recorded run ({@code replay RUN --inspector}).
     *
     * @param world makes the run's world afresh (its file: the one the run names)
     * @throws IOException when the run's agent or experiment is not here
     */
    public static PageEdits recorded(Inspector inspector, Path runDir, StepLog.Header header, Callable<SimWorld> world)
            throws IOException {
        Experiment e = Experiment.parse(header.experiment())
                .orElseThrow(() -> new IOException(runDir + ": unknown experiment '" + header.experiment() + "' in its step log"));
        return new PageEdits(inspector, runDir, header, e, WhatIf.originalAgent(header, e), world, null, null);
    }

    /** Edits of a live lockstep run writing its step log into {@code runDir}: what-ifs, and reloads when halted. */
    public static PageEdits live(Inspector inspector, Path runDir, StepLog.Header header, Experiment experiment,
            AgentSource original, Callable<SimWorld> world, Agent agent, Debugger debugger) {
        return new PageEdits(inspector, runDir, header, experiment, original, world, agent, debugger);
    }

    @Override
    public String source() {
        return original.text();
    }

    @Override
    public String whatIfRefusal() {
        return header.realTime() ? WhatIf.REAL_TIME_REFUSAL : null;
    }

    @Override
    public void whatIf(WhatIfJob job, String program) throws Exception {
        if (header.realTime()) {
            throw new IllegalStateException(WhatIf.REAL_TIME_REFUSAL);
        }
        AgentSource edited = original.withText(program);
        Path target = Path.of(runDir.toAbsolutePath().normalize() + "-whatif-" + count.incrementAndGet());
        WhatIf.Result r = WhatIf.run(world.call(), experiment, header.seed(), original, edited, job.getAtMs(),
                job.getSeconds(), target, new PrintStream(OutputStream.nullOutputStream()));
        Files.writeString(target.resolve("event-log.txt"), r.eventLog());
        StepArchive.history(inspector, target, job.getName());
        job.done(target.toString(), r.swappedAtMs(), divergence(runDir.resolve(StepLog.FILE), target.resolve(StepLog.FILE)));
    }

    @Override
    public Reload reloads() {
        return live == null || debugger == null ? Reload.NONE : Reload.AT_HALT;
    }

    @Override
    public String reload(String program) throws Exception {
        if (live == null || debugger == null) {
            return RunEdits.super.reload(program);
        }
        AgentProgram edited = WhatIf.parseEdited(original.withText(program)); // nothing is applied when it does not parse
        debugger.atHalt(() -> WhatIf.swapPlans(live, edited)).get(30, TimeUnit.SECONDS);
        return "the halted run has the edited plans; continue or step it";
    }

    /**
     * {@return the time of the first step where two step logs differ (-1: none, as far as both go)};
     * a log still being written is read as far as it is whole
     */
    static long divergence(Path a, Path b) throws IOException {
        try (BufferedReader x = lines(a); BufferedReader y = lines(b)) {
            x.readLine(); // the headers name different agents
            y.readLine();
            while (true) {
                String p = line(x), q = line(y);
                if (p == null || q == null) {
                    return -1;
                }
                if (!p.equals(q)) {
                    return StepLog.parse(q).timeMs();
                }
            }
        }
    }

    private static BufferedReader lines(Path file) throws IOException {
        return new BufferedReader(new InputStreamReader(new GZIPInputStream(Files.newInputStream(file), 1 << 16),
                StandardCharsets.UTF_8));
    }

    private static String line(BufferedReader in) throws IOException {
        try {
            String l = in.readLine();
            return l == null || !l.endsWith("}") ? null : l;
        } catch (EOFException e) {
            return null; // the member being written
        }
    }
}
