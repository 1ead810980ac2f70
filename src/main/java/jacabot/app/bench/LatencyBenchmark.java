package jacabot.app.bench;

import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.RealTimeRun;
import jacabot.experiments.link.LatencyStats;
import jacabot.experiments.link.LinkTimings;
import jacabot.robot.Experiment;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;
import jacabot.sim.world.BoxSpec;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The thesis' reactive and response times (Chapter 5 §3), with many samples. A supervisor moves a
 * box in front of the robot and away again, over and over; the middleware turns the distance
 * readings into {@code obstacle(true|false)} and the agent answers each change with {@code stop}.
 * Reactive time: the controller samples the reading → the plan it triggers is selected. Response
 * time: the agent's {@code stop} leaves the middleware → the controller applies it.
 */
public final class LatencyBenchmark {
    static final AgentSource AGENT = AgentSource.text("latency.asl", String.join("\n",
            "// The latency probe: react to every change of the obstacle property.",
            "!start.",
            "+!start <- lookupArtifact(\"middleware\", Id); focus(Id); accept; !go.",
            "+!go : connected(true) <- acquireData.",
            "+!go <- .wait(50); !go.",
            "+obstacle(true) <- stop.",
            "+obstacle(false) <- stop.", ""));
    /** Simulated milliseconds between two moves of the box (each move is one sample). */
    static final long TOGGLE_MS = 120;
    /**
     * Real time: first this many simulated seconds at {@link #WARM_UP_SPEED}, unmeasured, so that the
     * per-step code is compiled (at ×8 a method run once per step needs minutes to reach the JIT's
     * optimising tier, and the compiler takes one of the two cores meanwhile).
     */
    static final double WARM_UP_SECONDS = 400;
    static final double WARM_UP_SPEED = 50;
    /** Samples of each hand-off of the machine's floor (one per millisecond). */
    static final int FLOOR_SAMPLES = 3000;

    private final Path world;
    private final double seconds;
    private final double speed;
    private final PrintStream out;

    /** @param world experiment 1's world file */
    public LatencyBenchmark(Path world, double seconds, double speed, PrintStream out) {
        this.world = world;
        this.seconds = seconds;
        this.speed = speed;
        this.out = out;
    }

    public void run() throws Exception {
        out.println("| mode | samples | reactive median / p90 / p99 / max (ms) | response median / p90 / p99 / max (ms) |");
        out.println("|---|---|---|---|");
        var stages = realTime();
        lockstep();
        out.println();
        out.println("Real time, where the reactive time goes (every reading for the first two stages):");
        out.println("| stage | samples | median / p90 / p99 / max (ms) |");
        out.println("|---|---|---|");
        stage("sampled -> read off the socket by the middleware (transport)", stages.transport());
        stage("sampled -> taken by the artifact's serving loop (delivery)", stages.delivery());
        stage("sampled -> the plan it triggers is selected (reactive)", stages.reactive());
        out.println();
        out.println("The floor on this machine: one hand-off after 1 ms idle, as between two control steps:");
        out.println("| hand-off | samples | median / p90 / p99 / max (ms) |");
        out.println("|---|---|---|");
        stage("a parked thread woken by another (LockSupport.unpark)", WakeUpFloor.threadWakeUps(FLOOR_SAMPLES));
        stage("a byte over loopback TCP to a blocked reader", WakeUpFloor.socketWakeUps(FLOOR_SAMPLES));
    }

    private void stage(String name, LatencyStats s) {
        out.printf(Locale.ROOT, "| %s | %d | %s |%n", name, s.count(), ms(s));
    }

    private SimWorld world() throws Exception {
        return BaselineRunner.load(world, 1);
    }

    /** Moves the first box just ahead of the robot, or back to where it was. */
    private static final class BoxMover {
        private final SimWorld world;
        private final String box;
        private final Pose home;
        private boolean ahead;

        BoxMover(SimWorld world) {
            this.world = world;
            // our own probe box, parked in a corner (the world's boxes may be scripted away)
            this.box = "latency-probe";
            this.home = new Pose(-0.4, -0.4, 0);
            ObjectState any = world.supervisor().objects().stream()
                    .filter(o -> o.kind().name().equals("BOX")).findFirst().orElseThrow();
            world.supervisor().addBox(new BoxSpec(box, home.x(), home.z(), any.sizeX(), any.sizeZ(), 0,
                    any.height(), true, 1, any.color()));
        }

        void toggle() {
            Pose r = world.robots().get(0).pose();
            if (!ahead) {
                double h = Math.toRadians(r.heading());
                world.supervisor().move(box, r.x() + 0.1 * Math.cos(h), r.z() + 0.1 * Math.sin(h));
            } else {
                world.supervisor().move(box, home.x(), home.z());
            }
            ahead = !ahead;
        }
    }

    private LinkTimings realTime() throws Exception {
        SimWorld w = world();
        var quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        try (var run = new RealTimeRun(w, Experiment.OBSTACLE_AVOIDANCE, AGENT, 1, speed, quiet)) {
            run.start();
            run.runner().setSpeedFactor(Math.max(speed, WARM_UP_SPEED));
            run.runner().start();
            var mover = new BoxMover(w);
            long next = TOGGLE_MS * 10;
            boolean warm = false;
            while (w.time() < WARM_UP_SECONDS + seconds) {
                if (!warm && w.time() >= WARM_UP_SECONDS) {
                    run.runner().setSpeedFactor(speed);
                    run.timings().clear();
                    warm = true;
                }
                if (w.timeMs() >= next) {
                    mover.toggle();
                    next += TOGGLE_MS;
                }
                Thread.sleep(1);
            }
            run.runner().stop();
            print("real time x" + fmt(speed), run.timings().reactive(), run.timings().response());
            return run.timings();
        }
    }

    private void lockstep() throws Exception {
        SimWorld w = world();
        var quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        var run = new LockstepRun(w, null, Experiment.OBSTACLE_AVOIDANCE, AGENT, 1, quiet);
        var mover = new BoxMover(w);
        run.onStep(data -> {
            if (data.simTimeMs() >= TOGGLE_MS * 10 && data.simTimeMs() % TOGGLE_MS == 0) {
                mover.toggle();
            }
        });
        var result = run.runFor(seconds * 4);
        run.close();
        print("lockstep", run.reactiveTimes(), result.response());
        out.println();
        out.printf(Locale.ROOT, "Lockstep: %d commands answered a control step k; the latest was applied at step k+%d "
                + "(the controller applies a step's answer before the world leaves it).%n",
                result.timings().lockstepApplied(), result.timings().maxStepsLate());
    }

    private void print(String mode, LatencyStats reactive, LatencyStats response) {
        out.printf(Locale.ROOT, "| %s | %d / %d | %s | %s |%n", mode, reactive.count(), response.count(), ms(reactive), ms(response));
    }

    private static String ms(LatencyStats s) {
        return s.count() == 0 ? "-" : String.format(Locale.ROOT, "%.3f / %.3f / %.3f / %.3f", s.medianMicros() / 1000.0,
                s.p90Micros() / 1000.0, s.p99Micros() / 1000.0, s.maxMicros() / 1000.0);
    }

    private static String fmt(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.valueOf(d);
    }
}
