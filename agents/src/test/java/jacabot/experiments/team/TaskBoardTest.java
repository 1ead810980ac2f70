package jacabot.experiments.team;

import static jacabot.experiments.team.Ops.fails;
import static jacabot.experiments.team.Ops.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.CartagoException;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.Workspace;
import jacabot.experiments.geom.Segments;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;

/**
 * The team's task board: one claim per cylinder (claims are discs: a place and how far off it may
 * be, refused while they overlap another agent's), released, completed, freed when its agent
 * leaves; a cylinder carried is claimed where its robot is.
 */
class TaskBoardTest {
    private static int claim(Workspace ws, AgentId agent, double x, double z) {
        OpOutcome.Success s = ok(ws, agent, "board", "claim", x, z, new OpFeedbackParam<Integer>());
        return ((Number) s.outputs().get(2)).intValue();
    }

    private static int claim(Workspace ws, AgentId agent, double x, double z, double r) {
        OpOutcome.Success s = ok(ws, agent, "board", "claim", x, z, r, new OpFeedbackParam<Integer>());
        return ((Number) s.outputs().get(3)).intValue();
    }

    @Test
    void aPlaceClaimedByOneAgentCannotBeClaimedByAnotherWithinTheRadius() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");

            assertEquals(1, claim(ws, a, 0.30, 0.20));
            fails("claimed_by", List.of(a, 1), ws, b, "board", "claim", 0.35, 0.20, new OpFeedbackParam<Integer>());
            assertEquals(2, claim(ws, b, 0.45, 0.20), "15 cm away: another cylinder");
            assertEquals(1, claim(ws, a, 0.31, 0.21), "a's own claim again: the same id, a newer place");
            assertEquals(List.of(List.of(1, a, 0.31, 0.21, 0.05), List.of(2, b, 0.45, 0.20, 0.05)), sees.values("claimed"));
            assertEquals(List.of(List.of(0)), sees.values("completed"));
        }
    }

    @Test
    void theBoardLogsEachClaimItsReleaseWithTheReasonAndAVoidedClaim() throws CartagoException {
        List<String> lines = new ArrayList<>();
        CartagoLogger logger = new CartagoLogger() {
            @Override
            public void info(String source, String message) {
                lines.add(source + ": " + message);
            }

            @Override
            public void warning(String source, String message, Throwable cause) {
                lines.add(source + " warning: " + message);
            }
        };
        try (Workspace ws = Workspace.builder("team").logger(logger).build()) {
            ws.createArtifact("board", TaskBoard.class, 0.2);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            int id = claim(ws, a, 0.3, -0.2, 0.25);
            ok(ws, a, "board", "release", id, "notFoundAgain");
            claim(ws, a, 1.0, 1.0, 0.1);
            ok(ws, b, "board", "take", 1.0, 1.0, new OpFeedbackParam<Integer>());
            assertEquals(List.of("board: a claims 1 at (0.30, -0.20) r 0.25",
                    "board: a releases claim 1 at (0.30, -0.20): notFoundAgain",
                    "board: a claims 2 at (1.00, 1.00) r 0.10",
                    "board: a's claim 2 at (1.00, 1.00) void: b took the cylinder",
                    "board: b claims 3 at (1.00, 1.00) r 0.20"), lines);
        }
    }

    @Test
    void releaseAndCompleteBelongToTheClaimer() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class, 0.2);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");

            int id = claim(ws, a, 0, 0);
            fails("claimed_by", List.of(a, id), ws, b, "board", "claim", 0.15, 0.0);
            fails("not_yours", List.of(a, id), ws, b, "board", "release", id);
            fails("not_yours", List.of(a, id), ws, b, "board", "complete", id);
            fails("no_claim", List.of(99), ws, a, "board", "release", 99);
            ok(ws, a, "board", "release", id);
            int theirs = claim(ws, b, 0.15, 0);
            ok(ws, b, "board", "complete", theirs);
            fails("no_claim", List.of(theirs), ws, b, "board", "complete", theirs);
            assertEquals(List.of(), sees.values("claimed"));
            assertEquals(List.of(List.of(1)), sees.values("completed"));
        }
    }

    @Test
    void anAgentThatLeavesLosesItsClaims() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher cSees = Ops.watch(ws, "c", "board");
            AgentId c = new AgentId("c");
            claim(ws, a, 0, 0);
            claim(ws, a, 1, 1);
            int bs = claim(ws, b, 0.5, 0.5);
            ok(ws, a, "board", "releaseAll");
            assertEquals(List.of(List.of(bs, b, 0.5, 0.5, 0.05)), cSees.values("claimed"));
            claim(ws, a, 0, 0);

            ws.leave(a);
            ws.leave(b);
            assertEquals(List.of(), cSees.values("claimed"));
            assertEquals(List.of("claimsFreed[a, 1]", "claimsFreed[b, 1]"), cSees.signals);
            claim(ws, c, 0, 0);
        }
    }

    /**
     * Eight agents claim the same twelve cylinders at once, each from its own rough estimate of
     * their places and in its own order: every cylinder ends with exactly one claimer, and what an
     * agent focusing the board perceives never shows two agents' claims on one cylinder.
     */
    @Test
    void noTwoAgentsEverHoldAClaimOnTheSameCylinder() throws CartagoException {
        int agents = 8, cylinders = 12;
        double radius = TaskBoard.DEFAULT_RADIUS;
        List<String> violations = Collections.synchronizedList(new ArrayList<>());
        Ops.Watcher watcher = new Ops.Watcher() {
            @Override
            void changed() {
                List<List<Object>> held = values("claimed");
                for (int i = 0; i < held.size(); i++) {
                    for (int j = i + 1; j < held.size(); j++) {
                        List<Object> p = held.get(i), q = held.get(j);
                        double d = Math.hypot((Double) p.get(2) - (Double) q.get(2), (Double) p.get(3) - (Double) q.get(3));
                        if (d < radius && !p.get(1).equals(q.get(1))) {
                            violations.add(p + " and " + q);
                        }
                    }
                }
            }
        };
        for (int round = 0; round < 5; round++) {
            try (Workspace ws = Ops.workspace()) {
                ws.createArtifact("board", TaskBoard.class);
                AgentId w = ws.join("watcher", watcher);
                ok(ws, w, "body_watcher", "focus", "board");
                Random random = new Random(round);
                Map<CompletableFuture<OpOutcome>, Integer> calls = new HashMap<>();
                for (int k = 0; k < agents; k++) {
                    AgentId agent = ws.join("r" + k, new Ops.Watcher());
                    List<Integer> order = new ArrayList<>();
                    for (int c = 0; c < cylinders; c++) {
                        order.add(c);
                    }
                    Collections.shuffle(order, random);
                    for (int c : order) {
                        double x = 0.3 * (c % 4) + random.nextDouble(-0.03, 0.03), z = 0.3 * (c / 4) + random.nextDouble(-0.03, 0.03);
                        calls.put(Ops.start(ws, agent, "board", "claim", x, z), c);
                    }
                }
                Map<Integer, List<OpOutcome>> byCylinder = new HashMap<>();
                calls.forEach((call, c) -> byCylinder.computeIfAbsent(c, x -> new ArrayList<>()).add(call.join()));
                List<List<Object>> held = watcher.values("claimed");
                assertEquals(cylinders, held.size(), "one claim per cylinder: " + held);
                for (int c = 0; c < cylinders; c++) {
                    List<OpOutcome> outcomes = byCylinder.get(c);
                    assertEquals(1, outcomes.stream().filter(OpOutcome::succeeded).count(), "cylinder " + c + ": one claimer");
                    assertTrue(outcomes.stream().filter(o -> !o.succeeded())
                            .allMatch(o -> ((OpOutcome.Failure) o).reasonFunctor().equals("claimed_by")), outcomes::toString);
                }
                ws.leave(w);
                watcher.properties.clear();
            }
        }
        assertEquals(List.of(), violations);
    }

    @Test
    void aCylinderTakenIsTheTakersWhoeverHadClaimedItsPlace() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class, 0.2);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");

            int bs = claim(ws, b, 0.50, 0.50);           // b goes for the cylinder at (0.5, 0.5)
            int elsewhere = claim(ws, a, -0.5, -0.5);    // a went for another one...
            OpOutcome.Success took = ok(ws, a, "board", "take", 0.55, 0.5, new OpFeedbackParam<Integer>());
            int id = ((Number) took.outputs().get(2)).intValue(); // ...and picked b's up on the way
            assertTrue(id != bs && id != elsewhere, "a new claim for the cylinder in a's gripper");
            assertEquals(List.of(List.of(id, a, 0.55, 0.5, TaskBoard.CARRIED_RADIUS)), sees.values("claimed"),
                    "b's claim void, a's other one released");
            fails("no_claim", List.of(bs), ws, b, "board", "release", bs);
            OpOutcome.Success again = ok(ws, a, "board", "take", 0.56, 0.5, new OpFeedbackParam<Integer>());
            assertEquals(id, ((Number) again.outputs().get(2)).intValue(), "its own claim there: the same claim");
        }
    }

    /**
     * A robot picking a cylinder next to a robot that carries one does not void the carried
     * cylinder's claim: that one is in the other's gripper, and its robot completes it on delivery.
     */
    @Test
    void aTakeBesideAnotherRobotLeavesTheClaimOfTheCylinderItCarries() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class, 0.2);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            OpOutcome.Success aTook = ok(ws, a, "board", "take", 0.50, 0.50, new OpFeedbackParam<Integer>());
            int carried = ((Number) aTook.outputs().get(2)).intValue();
            ok(ws, b, "board", "take", 0.55, 0.50, new OpFeedbackParam<Integer>()); // b picks one 5 cm away
            ok(ws, a, "board", "complete", carried);                                  // a delivers its own
        }
    }

    /**
     * Two robots' estimates of one cylinder seen from afar lie 0.35 m apart: their discs (how far
     * off each may be) overlap, so the second is refused; a claim near its cylinder is narrow and
     * leaves a neighbour 0.3 m away free; the claimer's nearer estimate is the same claim, narrower.
     */
    @Test
    void claimsAreDiscsThatMustNotOverlapAnotherAgents() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class, 0.2);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");

            int far = claim(ws, a, 1.0, 1.0, 0.4);                        // seen from 1.1 m
            fails("claimed_by", List.of(a, far), ws, b, "board", "claim", 1.35, 1.0, 0.3, new OpFeedbackParam<Integer>());
            assertEquals(far, claim(ws, a, 1.05, 1.02, 0.1), "nearer: the same claim, narrower");
            int neighbour = claim(ws, b, 1.35, 1.0, 0.15);                // now clear of a's disc
            assertTrue(neighbour != far);
            assertEquals(List.of(List.of(far, a, 1.05, 1.02, 0.1), List.of(neighbour, b, 1.35, 1.0, 0.15)), sees.values("claimed"));
            fails("bad_radius", List.of(0.0), ws, a, "board", "claim", 0.0, 0.0, 0.0, new OpFeedbackParam<Integer>());
        }
    }

    /**
     * One cylinder, at (0.52, 0.069), half hidden from one robot by a box: seen from (0.844, 0.676)
     * it was estimated at (0.663, 0.334), 0.39 m away (it is 0.69 m), and seen from (0.907, 0.022)
     * at (0.617, -0.107): discs of 0.194 and 0.173 m round the estimates miss each other and two
     * robots held a claim on it at once (team world 12, four robots). Swept on along each bearing,
     * the first claim reaches the cylinder and the second is refused; a cylinder well off the
     * first bearing stays free, and the swept claim's own nearer estimate is the same claim.
     */
    @Test
    void aSightingsClaimIsSweptAlongItsBearingSoThatAnUnderestimatedDistanceStillMeetsTheOther() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());

            claim(ws, a, 0.663, 0.334, 0.194);                            // as discs, both pass: the double claim
            claim(ws, b, 0.617, -0.107, 0.173);
            ok(ws, a, "board", "releaseAll");
            ok(ws, b, "board", "releaseAll");
            double[] aLine = sweep(0.844, 0.676, 0.663, 0.334, 0.194);
            double[] bLine = sweep(0.907, 0.022, 0.617, -0.107, 0.173);
            int first = claimAlong(ws, a, 0.663, 0.334, 0.194, aLine);
            assertTrue(Segments.toSegment(0.52, 0.069, 0.663, 0.334, aLine[0], aLine[1]) < 0.194, "the sweep reaches the cylinder");
            fails("claimed_by", List.of(a, first), ws, b, "board", "claimAlong", 0.617, -0.107, 0.173, bLine[0], bLine[1],
                    new OpFeedbackParam<Integer>());                      // swept, the second is refused
            claimAlong(ws, b, 0.2, 0.9, 0.1, sweep(0.6, 1.2, 0.2, 0.9, 0.1)); // far off a's bearing: another cylinder
            assertEquals(first, claimAlong(ws, a, 0.55, 0.12, 0.1, sweep(0.844, 0.676, 0.55, 0.12, 0.1)), "nearer: the same claim");
        }
    }

    /** {@return the far end of a sighting's claim from (x, z) estimated at (ex, ez): twice r beyond the estimate} */
    private static double[] sweep(double x, double z, double ex, double ez, double r) {
        double d = Math.hypot(ex - x, ez - z);
        return new double[] {ex + (ex - x) / d * 2 * r, ez + (ez - z) / d * 2 * r};
    }

    private static int claimAlong(Workspace ws, AgentId agent, double x, double z, double r, double[] to) {
        OpOutcome.Success s = ok(ws, agent, "board", "claimAlong", x, z, r, to[0], to[1], new OpFeedbackParam<Integer>());
        return ((Number) s.outputs().get(5)).intValue();
    }

    /**
     * A cylinder carried away is claimed where its robot last said it was: another robot that
     * sights it in the gripper cannot claim it on the way; once put down, the claim stays there.
     */
    @Test
    void aCarriedCylindersClaimFollowsItsRobotUntilPutDown() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class, 0.2);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");

            OpOutcome.Success took = ok(ws, a, "board", "take", 0.0, 0.0, new OpFeedbackParam<Integer>());
            int id = ((Number) took.outputs().get(2)).intValue();
            ok(ws, a, "board", "at", 0.6, 0.4);                          // a carries it away
            assertEquals(List.of(List.of(id, a, 0.6, 0.4, TaskBoard.CARRIED_RADIUS)), sees.values("claimed"));
            fails("claimed_by", List.of(a, id), ws, b, "board", "claim", 0.75, 0.45, 0.1, new OpFeedbackParam<Integer>());
            int left = claim(ws, b, 0.0, 0.0, 0.1);                       // where it was: free
            assertTrue(left != id);
            ok(ws, a, "board", "putDown", 0.65, 0.4);
            ok(ws, a, "board", "at", 0.3, 0.4);                           // no longer follows a
            assertEquals(List.of(List.of(id, a, 0.65, 0.4, 0.1), List.of(left, b, 0.0, 0.0, 0.1)), sees.values("claimed"));
            ok(ws, b, "board", "putDown", 0.0, 0.0);                      // carries nothing: nothing changes
            assertEquals(2, sees.values("claimed").size());
        }
    }

    @Test
    void robotsPublishTheirPlacesOneEach() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");
            ok(ws, a, "board", "at", 0.1, 0.2);
            ok(ws, b, "board", "at", -0.3, 0.4);
            ok(ws, a, "board", "at", 0.15, 0.2);
            assertEquals(List.of(List.of(a, 0.15, 0.2), List.of(b, -0.3, 0.4)), sees.values("robotAt"));
            ws.leave(b);
            assertEquals(List.of(List.of(a, 0.15, 0.2)), sees.values("robotAt"), "a robot gone is nowhere");
        }
    }

    @Test
    void oneRobotAtATimeAtTheStoragePoint() throws CartagoException, InterruptedException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("board", TaskBoard.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher()), c = ws.join("c", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "board");
            ok(ws, a, "board", "awaitStorageTurn"); // free: at once
            CompletableFuture<OpOutcome> bWaits = Ops.start(ws, b, "board", "awaitStorageTurn");
            awaitQueue(sees, List.of(a, b)); // b joins from a thread of its own, then c
            CompletableFuture<OpOutcome> cWaits = Ops.start(ws, c, "board", "awaitStorageTurn");
            awaitQueue(sees, List.of(a, b, c));
            assertTrue(!bWaits.isDone() && !cWaits.isDone(), "b and c wait while a is at the storage point");
            ok(ws, a, "board", "storageDone");
            assertTrue(bWaits.join().succeeded(), "b's turn");
            ws.leave(b); // b's agent gone while at the storage point: c's turn
            assertTrue(cWaits.join().succeeded(), "c's turn");
            assertEquals(List.of(List.of(List.of(c))), sees.values("storageQueue"));
        }
    }

    private static void awaitQueue(Ops.Watcher sees, List<AgentId> queue) throws InterruptedException {
        for (int i = 0; i < 300 && !sees.values("storageQueue").equals(List.of(List.of(queue))); i++) {
            Thread.sleep(10);
        }
        assertEquals(List.of(List.of(queue)), sees.values("storageQueue"));
    }
}
