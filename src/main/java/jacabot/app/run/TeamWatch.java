package jacabot.app.run;

import jacabot.experiments.team.ChargerQueue;
import jacabot.experiments.team.TaskBoard;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.world.AreaSpec;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What a team run's shared artifacts show, read after every control step against the world's
 * ground truth: how many claims were made, whether two robots ever held claims on one cylinder
 * (each claim names the cylinder its robot carries, else the one nearest its place when it was
 * placed there), and how long each robot waited at the charger: waiting in the queue behind
 * another robot (it has arrived: {@link ChargerQueue#waiting}) with its centre within
 * {@link #AT_CHARGER} of the charger. A robot that booked its place and works on meanwhile is
 * queued, not waiting, wherever it works (counted while it was near the charger before: a robot
 * booked and searching beside the charger for 85 s counted as waiting). Stricter than "waits
 * while another sits charged on it": a wait behind a robot still charging counts too.
 */
public final class TeamWatch {
    /** A claim farther than this from every cylinder names none, metres. */
    static final double CLAIM_REACH = 0.3;
    /** A queued robot this near the charger (centre to centre, metres) is waiting at it. */
    static final double AT_CHARGER = 0.5;

    private final SimWorld world;
    private final TaskBoard board;
    private final ChargerQueue charger;
    private final List<String> robots;
    private final Map<String, Long> waitingSince = new HashMap<>();
    private final Map<String, Double> longestWait = new HashMap<>();
    private final Set<String> doubled = new HashSet<>();
    /** Each claim's place and the cylinder it named when placed there, by claim id. */
    private final Map<Integer, Named> named = new HashMap<>();
    private int claims;
    private int doubleClaims;
    private int chargerWaits;

    private record Named(double x, double z, String cylinder) {
    }

    TeamWatch(SimWorld world, TaskBoard board, ChargerQueue charger, List<String> robots) {
        this.world = world;
        this.board = board;
        this.charger = charger;
        this.robots = List.copyOf(robots);
    }

    void afterStep(long nowMs) {
        List<TaskBoard.Held> held = board.claims();
        for (TaskBoard.Held h : held) {
            claims = Math.max(claims, h.id());
        }
        if (!held.isEmpty()) {
            checkDoubleClaims(held); // names every new claim, counts pairs
        }
        if (named.size() > held.size()) {
            named.keySet().retainAll(held.stream().map(TaskBoard.Held::id).toList());
        }
        List<String> queue = charger.queued();
        List<String> arrived = charger.waiting();
        for (int i = 0; i < queue.size(); i++) {
            String r = queue.get(i);
            boolean waiting = i > 0 && arrived.contains(r) && nearCharger(r);
            if (waiting && !waitingSince.containsKey(r)) {
                waitingSince.put(r, nowMs);
                chargerWaits++;
            }
            if (!waiting) {
                stopWaiting(r, nowMs);
            }
        }
        for (String r : List.copyOf(waitingSince.keySet())) {
            if (!queue.contains(r)) {
                stopWaiting(r, nowMs);
            }
        }
    }

    private boolean nearCharger(String robot) {
        AreaSpec c = world.spec().charger();
        return c != null && world.robots().stream().filter(r -> r.name().equals(robot))
                .anyMatch(r -> Math.hypot(r.pose().x() - c.x(), r.pose().z() - c.z()) < AT_CHARGER);
    }

    private void stopWaiting(String robot, long nowMs) {
        Long since = waitingSince.remove(robot);
        if (since != null) {
            longestWait.merge(robot, (nowMs - since) / 1000.0, Math::max);
        }
    }

    /** Names each claim's cylinder; two agents' claims naming one cylinder are counted once per pair. */
    private void checkDoubleClaims(List<TaskBoard.Held> held) {
        List<ObjectState> cylinders = world.supervisor().objects().stream().filter(o -> o.kind() == ObjectKind.CYLINDER).toList();
        Map<String, TaskBoard.Held> byCylinder = new HashMap<>();
        for (TaskBoard.Held h : held) {
            // a claim's cylinder is the one its robot carries, else the one nearest its place when
            // the claim was placed there (a robot carrying another cylinder past it later does not
            // make it name that one)
            String carried = world.supervisor().carried(h.agent());
            Named n = named.get(h.id());
            if (n == null || n.x() != h.x() || n.z() != h.z()) {
                n = new Named(h.x(), h.z(), nearest(cylinders, h.x(), h.z()));
                named.put(h.id(), n);
            }
            String c = carried != null ? carried : n.cylinder();
            if (c == null) {
                continue;
            }
            TaskBoard.Held other = byCylinder.putIfAbsent(c, h);
            if (other != null && !other.agent().equals(h.agent()) && doubled.add(other.id() + "/" + h.id())) {
                doubleClaims++;
            }
        }
    }

    private static String nearest(List<ObjectState> cylinders, double x, double z) {
        String best = null;
        double bestD = CLAIM_REACH;
        for (ObjectState o : cylinders) {
            double d = Math.hypot(o.pose().x() - x, o.pose().z() - z);
            if (d < bestD) {
                bestD = d;
                best = o.id();
            }
        }
        return best;
    }

    /** {@return the claims made on the board (its last claim's id)} */
    public int claims() {
        return claims;
    }

    /** {@return how many times two robots held claims naming one cylinder} */
    public int doubleClaims() {
        return doubleClaims;
    }

    /** {@return how many times a robot waited at the charger behind another} */
    public int chargerWaits() {
        return chargerWaits;
    }

    /** {@return the longest a robot waited at the charger behind another, seconds (0 when it never waited)} */
    public double longestChargerWait(String robot) {
        Long since = waitingSince.get(robot);
        double open = since == null ? 0 : (world.timeMs() - since) / 1000.0;
        return Math.max(open, longestWait.getOrDefault(robot, 0.0));
    }

    /** {@return the longest any robot of the team waited for the charger, seconds} */
    public double longestChargerWait() {
        return robots.stream().mapToDouble(this::longestChargerWait).max().orElse(0);
    }
}
