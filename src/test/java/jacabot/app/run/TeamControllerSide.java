package jacabot.app.run;

import jacabot.app.world.TeamWorld;
import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.TeamLockstep;
import jacabot.robot.link.LinkSecret;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

/**
 * For the team's two-process tests: the controllers' process as {@code jacabot controller --lockstep
 * --world FILE} runs it (a {@link TeamLockstep} over TCP, robot i to port i), on its own world and
 * thread; each robot's event log and the wall-clock instant of its fail-safe are kept.
 */
final class TeamControllerSide implements AutoCloseable {
    final SimWorld world;
    final TeamLockstep team;
    final Map<String, List<String>> events = new LinkedHashMap<>();
    final Map<String, Long> failSafeNanos = new ConcurrentHashMap<>();
    private final Thread thread;
    private volatile Throwable failed;

    /** Starts the controllers of the team world's first {@code robots} robots; they step {@code seconds} once all are connected. */
    TeamControllerSide(int robots, List<Integer> ports, LinkSecret secret, double seconds) throws Exception {
        world = world(robots);
        List<RobotController> controllers = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            String name = world.robots().get(i).name();
            List<String> log = new CopyOnWriteArrayList<>();
            events.put(name, log);
            var cc = ControllerConfig.defaults().withAddress("127.0.0.1", ports.get(i)).withSecret(secret).withLockstep(true)
                    .withRobot(name).withBackoff(20, 200).withEventLog(log::add).withLog(line -> {
                        if (line.startsWith("fail-safe")) {
                            failSafeNanos.putIfAbsent(name, System.nanoTime());
                        }
                    });
            controllers.add(new RobotController(world, cc));
        }
        team = new TeamLockstep(world, controllers, null);
        controllers.forEach(RobotController::start);
        thread = new Thread(() -> {
            try {
                if (!team.awaitConnected(TimeUnit.SECONDS.toMillis(60)).isEmpty()) {
                    throw new IllegalStateException("not every robot connected");
                }
                long end = Math.round(seconds * 1000);
                while (world.timeMs() < end && team.anyConnected()) {
                    team.runner().stepOnce();
                }
            } catch (Throwable t) {
                failed = t;
            } finally {
                team.close(); // goodbye
            }
        }, "team-controllers");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Starts {@code agents} (made with {@link TeamLockstepRun#remoteController}) on a thread of its own,
     * waits for its links to listen, then starts the controllers against them.
     */
    static TeamControllerSide against(TeamLockstepRun agents, LinkSecret secret, double seconds) throws Exception {
        Throwable[] failed = new Throwable[1];
        Thread thread = new Thread(() -> {
            try {
                agents.runFor(seconds);
            } catch (Throwable t) {
                failed[0] = t;
            }
        }, "team-agents");
        thread.start();
        long listening = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (agents.listeningPorts().isEmpty() && failed[0] == null && System.nanoTime() < listening) {
            Thread.sleep(10);
        }
        if (agents.listeningPorts().size() != agents.robots().size()) {
            throw new AssertionError("a link per robot: " + agents.listeningPorts() + ", " + failed[0]);
        }
        TeamControllerSide side = new TeamControllerSide(agents.robots().size(), agents.listeningPorts(), secret, seconds);
        side.agents = thread;
        side.agentsFailed = failed;
        return side;
    }

    private Thread agents;
    private Throwable[] agentsFailed;

    /** Waits for the end of both sides' runs. {@return the first failure of the controllers' or the agents', or null} */
    Throwable joinBoth() throws InterruptedException {
        Throwable c = join();
        agents.join(TimeUnit.SECONDS.toMillis(120));
        if (agents.isAlive()) {
            return new AssertionError("the agents' side did not end");
        }
        return c != null ? c : agentsFailed[0];
    }

    static SimWorld world(int robots) throws Exception {
        var spec = WorldFileReader.read(Path.of(System.getProperty("jacabot.rootDir", "."), "worlds/team-delivery.json"));
        return SimWorld.of(TeamWorld.firstRobots(spec, robots));
    }

    /** Waits for the end of the controllers' run. {@return a failure of theirs, or null} */
    Throwable join() throws InterruptedException {
        thread.join(TimeUnit.SECONDS.toMillis(180));
        return thread.isAlive() ? new AssertionError("the controllers did not finish") : failed;
    }

    @Override
    public void close() {
        team.close();
    }
}
