package jacabot.app.bench;

import jacabot.app.run.AgentSource;
import jacabot.app.run.TeamLockstepRun;
import jacabot.app.world.TeamWorld;
import jacabot.sim.SimWorld;
import jacabot.sim.world.WorldSpec;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * A team's cost per simulated second against one robot's (thesis Chapter 6): team-delivery in
 * lockstep in one process ({@link TeamLockstepRun}: agents, artifacts, in-memory links, controllers,
 * physics, devices) with the team world's first robot alone and with its first N, runs alternated in
 * one JVM after warm-up, so that both sizes meet the same JIT and the same load. The target: a
 * 4-robot run at most 4.5 times a 1-robot run per simulated second.
 */
public final class TeamSimulationBenchmark {
    private final WorldSpec world;
    private final AgentSource agent;
    private final int robots;
    private final double seconds;
    private final long seed;
    private final int warmups;
    private final int measuredRuns;
    private final PrintStream out;
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();

    /** A run's costs: wall and this thread's CPU nanoseconds, physics and devices, reasoning cycles. */
    private record Cost(long wall, long cpu, long world, long cycles) {
    }

    /**
     * @param world  a team world with at least {@code robots} robots
     * @param robots the team's size measured against one robot
     */
    public TeamSimulationBenchmark(WorldSpec world, AgentSource agent, int robots, double seconds, long seed, int warmups,
            int measuredRuns, PrintStream out) {
        if (robots < 1 || robots > world.robots().size()) {
            throw new IllegalArgumentException("a team of 1.." + world.robots().size() + " robots in this world, got " + robots);
        }
        BenchRuns.check(warmups, measuredRuns);
        this.world = world;
        this.agent = agent;
        this.robots = robots;
        this.seconds = seconds;
        this.seed = seed;
        this.warmups = warmups;
        this.measuredRuns = measuredRuns;
        this.out = out;
    }

    public void run() throws Exception {
        for (int i = 0; i < warmups; i++) {
            measure(1);
            measure(robots);
        }
        List<Cost> one = new ArrayList<>(), team = new ArrayList<>();
        List<Double> wallRatios = new ArrayList<>(), cpuRatios = new ArrayList<>();
        for (int i = 0; i < measuredRuns; i++) {
            Cost a = measure(1);
            Cost b = measure(robots);
            one.add(a);
            team.add(b);
            wallRatios.add((double) b.wall() / a.wall());
            cpuRatios.add((double) b.cpu() / a.cpu());
        }
        out.printf(Locale.ROOT, "team-delivery in lockstep in one process, world '%s', seed %d, %.0f s simulated per run: "
                + "%d warm-up pairs, then %d measured pairs (1 robot, then %d), alternated%n", world.name(), seed, seconds, warmups,
                measuredRuns, robots);
        out.println("| robots | wall ms per simulated s (median) | CPU ms of the run's thread per simulated s | physics and devices, ms per simulated s | reasoning cycles per simulated s |");
        out.println("|---|---|---|---|---|");
        row(1, one);
        row(robots, team);
        double wall = median(wallRatios), cpu = median(cpuRatios);
        out.printf(Locale.ROOT, "%d robots cost %.2fx one robot per simulated second (wall clock; the run thread's CPU %.2fx), median of the pairs' ratios "
                + "(%s); the target for 4 robots: at most 4.5x.%n", robots, wall, cpu,
                wallRatios.stream().map(r -> String.format(Locale.ROOT, "%.2f", r)).collect(Collectors.joining(" ")));
    }

    private void row(int n, List<Cost> costs) {
        out.printf(Locale.ROOT, "| %d | %.1f | %.1f | %.1f | %.0f |%n", n, median(costs.stream().map(c -> c.wall() / 1e6 / seconds).toList()),
                median(costs.stream().map(c -> c.cpu() / 1e6 / seconds).toList()),
                median(costs.stream().map(c -> c.world() / 1e6 / seconds).toList()),
                median(costs.stream().map(c -> c.cycles() / seconds).toList()));
    }

    private Cost measure(int n) throws Exception {
        SimWorld w = SimWorld.of(TeamWorld.firstRobots(world, n));
        try (TeamLockstepRun run = new TeamLockstepRun(w, agent, seed, new PrintStream(OutputStream.nullOutputStream()))) {
            run.stepLogs(false); // the per-step text logs are for comparisons, not part of a run's cost
            long cpu0 = threads.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            run.runFor(seconds);
            long wall = System.nanoTime() - t0;
            long cpu = threads.getCurrentThreadCpuTime() - cpu0;
            long[] stepCost = w.stepCost();
            return new Cost(wall, cpu, stepCost[0] + stepCost[1], run.cycles());
        }
    }

    private static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        sorted.sort(Double::compare);
        return sorted.get(sorted.size() / 2);
    }
}
