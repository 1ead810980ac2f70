package jacabot.experiments.team;

import static jacabot.experiments.team.Ops.fails;
import static jacabot.experiments.team.Ops.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.CartagoException;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.Workspace;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The team's search map: what one robot has looked over is not another's next search point, two
 * robots' points lie apart, a point moves on once its cell is seen, and an agent that leaves loses
 * its point.
 */
class SearchMapTest {
    private static double[] searchFrom(Workspace ws, AgentId agent, double x, double z) {
        OpOutcome.Success s = ok(ws, agent, "search", "searchFrom", x, z, new OpFeedbackParam<Double>(), new OpFeedbackParam<Double>());
        return new double[] {((Number) s.outputs().get(2)).doubleValue(), ((Number) s.outputs().get(3)).doubleValue()};
    }

    private static SearchMap map(Workspace ws) throws CartagoException {
        return ws.artifactObject(ws.createArtifact("search", SearchMap.class), SearchMap.class).orElseThrow();
    }

    @Test
    void theFloorOneRobotLookedOverIsNotTheNextSearchPoint() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            SearchMap map = map(ws);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            fails("no_arena", List.of(), ws, a, "search", "searchFrom", 0.0, 0.0, new OpFeedbackParam<Double>(), new OpFeedbackParam<Double>());
            ok(ws, a, "search", "searchArea", 2.0, 2.0, 0.9, 0.9, 0.3);
            int all = map.unseen();
            // a looks east from the arena's west side: the floor ahead of it is seen
            ok(ws, a, "search", "looked", -0.8, 0.0, 0.0, false);
            assertTrue(map.unseen() < all - 4, "cells seen: " + (all - map.unseen()));
            // b, just beside a, is sent elsewhere than the floor a looked over
            double[] p = searchFrom(ws, b, -0.7, 0.05);
            double dx = p[0] + 0.8, dist = Math.hypot(dx, p[1]);
            boolean inAsView = dist < SearchMap.AROUND
                    || dist < SearchMap.VIEW_RANGE && dx > dist * Math.cos(Math.toRadians(SearchMap.VIEW_HALF_ANGLE));
            assertTrue(!inAsView, "b's point: " + p[0] + ", " + p[1]);
            assertTrue(Math.hypot(p[0] + 0.7, p[1] - 0.05) < 0.4, "the nearest such cell: " + p[0] + ", " + p[1]);
            // never into the storage area
            assertTrue(Math.hypot(p[0] - 0.9, p[1] - 0.9) >= 0.3);
        }
    }

    @Test
    void twoRobotsPointsLieApartAndAPointMovesOnOnceSeen() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            SearchMap map = map(ws);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "watcher", "search");
            ok(ws, a, "search", "searchArea", 2.0, 2.0, 0.9, 0.9, 0.3);
            double[] pa = searchFrom(ws, a, 0.0, 0.0), pb = searchFrom(ws, b, 0.0, 0.0);
            assertTrue(Math.hypot(pa[0] - pb[0], pa[1] - pb[1]) >= SearchMap.SPREAD, "a and b sent to one place");
            assertEquals(List.of(List.of(a, pa[0], pa[1]), List.of(b, pb[0], pb[1])), sees.values("searchPoint"));
            // b looks over a's point: a's point moves on, to a cell not seen
            ok(ws, b, "search", "looked", pa[0], pa[1], 0.0, true);
            List<Object> aNow = sees.values("searchPoint").get(0);
            assertNotEquals(List.of(a, pa[0], pa[1]), aNow);
            // a robot that stops searching has no point; one that leaves neither
            ok(ws, a, "search", "looked", 0.0, 0.0, 0.0, false);
            assertEquals(List.of(b), sees.values("searchPoint").stream().map(v -> v.get(0)).toList());
            ws.leave(b);
            assertEquals(List.of(), sees.values("searchPoint"));
        }
    }

    @Test
    void theSearchBeginsAgainOnceEveryCellIsSeen() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            SearchMap map = map(ws);
            AgentId a = ws.join("a", new Ops.Watcher());
            ok(ws, a, "search", "searchArea", 1.0, 1.0, 0.4, 0.4, 0.2);
            int all = map.unseen();
            for (double x = -0.375; x < 0.5; x += 0.25) {
                for (double z = -0.375; z < 0.5; z += 0.25) {
                    ok(ws, a, "search", "looked", x, z, 0.0, false);
                }
            }
            assertEquals(0, map.unseen());
            searchFrom(ws, a, 0.0, 0.0);
            assertEquals(all, map.unseen(), "the map begun again");
        }
    }

    @Test
    void aSpottedCylinderIsTheNextPointUntilARobotLooksAtItFromNear() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            map(ws);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            ok(ws, a, "search", "searchArea", 2.0, 2.0, 0.9, 0.9, 0.3);
            ok(ws, b, "search", "spotted", -0.6, 0.7);
            ok(ws, b, "search", "spotted", -0.5, 0.7);   // the same cylinder: one spot
            double[] p = searchFrom(ws, a, 0.5, -0.5);
            assertEquals(-0.6, p[0], 1e-9);
            assertEquals(0.7, p[1], 1e-9);
            double[] q = searchFrom(ws, b, 0.5, -0.5);
            assertTrue(Math.hypot(q[0] + 0.6, q[1] - 0.7) > 0.5, "b is not sent to a's spot");
            // a looks at it from 0.4 m: done, a's point moves on
            ok(ws, a, "search", "looked", -1.0, 0.7, 0.0, true);
            double[] r = searchFrom(ws, a, -1.0, 0.7);
            assertTrue(Math.hypot(r[0] + 0.6, r[1] - 0.7) > 0.01, "the spot is done");
        }
    }
}
