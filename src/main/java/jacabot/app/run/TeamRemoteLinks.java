package jacabot.app.run;

import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.MiddlewareLink;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * The agents' side of a team whose controllers are in another process ({@code jacabot controller
 * --lockstep --world FILE}): one {@link MiddlewareLink} per robot, robot i's on port {@code base + i}
 * (each on a free port when {@code base} is 0), authenticated with the user's link secret as for one
 * robot; and the barrier: a step is answered only once every robot still in the team has sent it.
 */
final class TeamRemoteLinks implements AutoCloseable {
    /** Safety net: controllers silent this long are broken, not slow (once every one has connected). */
    private static final long SILENCE_LIMIT_SECONDS = 60;

    private final List<TeamMember> members;
    private final List<MiddlewareLink> links;

    private TeamRemoteLinks(List<TeamMember> members, List<MiddlewareLink> links) {
        this.members = members;
        this.links = links;
    }

    /** Opens every robot's link and hands its events to the robot's member. */
    static TeamRemoteLinks open(List<TeamMember> members, int basePort, Consumer<String> log) throws IOException {
        List<MiddlewareLink> links = new ArrayList<>();
        try {
            for (int i = 0; i < members.size(); i++) {
                links.add(MiddlewareLink.open(LinkConfig.defaults().withPort(basePort == 0 ? 0 : basePort + i).withLog(log)));
            }
        } catch (IOException | RuntimeException e) {
            links.forEach(MiddlewareLink::close);
            throw e;
        }
        for (int i = 0; i < members.size(); i++) {
            members.get(i).connect(links.get(i));
        }
        return new TeamRemoteLinks(members, links);
    }

    /** {@return the ports listened on, in the robots' order} */
    List<Integer> ports() {
        return links.stream().map(MiddlewareLink::port).toList();
    }

    /**
     * Waits until every robot still in the team (its agent in, its link not ended) has sent its next
     * step, as long as it takes for the controllers to connect. {@return the steps' simulated time,
     * or −1 when every link has ended (the controllers said goodbye) or {@code stopped} says so}
     *
     * @throws IllegalStateException when a controller of another robot connects on a robot's port,
     *                               the robots' steps disagree, or the controllers fall silent
     */
    long awaitSteps(Object arrivals, BooleanSupplier stopped) throws InterruptedException {
        long lastNews = System.nanoTime();
        int seen = -1;
        synchronized (arrivals) {
            while (true) {
                checkRobots();
                int waiting = 0, live = 0, arrived = 0;
                long time = -1;
                for (TeamMember m : members) {
                    TeamStepCollector c = m.collector();
                    if (m.left() != null || c.ended()) {
                        continue;
                    }
                    live++;
                    if (c.hasStep()) {
                        arrived++;
                        time = c.peekTime();
                        for (TeamMember o : members) {
                            long t = o.collector().peekTime();
                            if (t >= 0 && t != time) {
                                throw new IllegalStateException("the robots' steps disagree: " + m.robot() + " at t=" + time
                                        + " ms, " + o.robot() + " at t=" + t + " ms");
                            }
                        }
                    } else {
                        waiting++;
                    }
                }
                if (live == 0 || stopped.getAsBoolean()) {
                    return -1;
                }
                if (waiting == 0) {
                    return time;
                }
                if (arrived != seen) {
                    seen = arrived;
                    lastNews = System.nanoTime();
                }
                boolean allConnected = members.stream().allMatch(m -> m.collector().connectedOnce() || m.left() != null);
                if (allConnected && System.nanoTime() - lastNews > TimeUnit.SECONDS.toNanos(SILENCE_LIMIT_SECONDS)) {
                    throw new IllegalStateException("no step from the controllers of " + waitingFor() + " for "
                            + SILENCE_LIMIT_SECONDS + " s");
                }
                arrivals.wait(100);
            }
        }
    }

    /**
     * After the run's last step: waits until every link still up has ended (the controllers' goodbye)
     * or sent a further step (a controller running on past this side's duration), at most the silence limit.
     */
    void awaitGoodbyes(Object arrivals) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(SILENCE_LIMIT_SECONDS);
        synchronized (arrivals) {
            while (System.nanoTime() < end && members.stream().anyMatch(
                    m -> m.left() == null && !m.collector().ended() && !m.collector().hasStep())) {
                arrivals.wait(100);
            }
        }
    }

    private void checkRobots() {
        for (int i = 0; i < members.size(); i++) {
            String robot = members.get(i).collector().robot();
            if (robot != null && !robot.equals(members.get(i).robot())) {
                throw new IllegalStateException("port " + links.get(i).port() + " is " + members.get(i).robot()
                        + "'s, and the controller of " + robot + " connected to it: the same world file and team on both sides?");
            }
        }
    }

    private String waitingFor() {
        return String.join(", ", members.stream().filter(m -> m.left() == null && !m.collector().ended()
                && !m.collector().hasStep()).map(TeamMember::robot).toList());
    }

    @Override
    public void close() {
        links.forEach(MiddlewareLink::close);
    }
}
