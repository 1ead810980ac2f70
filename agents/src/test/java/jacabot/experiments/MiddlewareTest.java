package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import jacabot.cartago.Workspace;
import jacabot.experiments.link.StepData;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The middleware artifacts' interpretation of readings (thesis Chapter 4), fed step by step in
 * lockstep mode as the experiment runner feeds them, and observed as an agent would observe them.
 */
class MiddlewareTest {
    /** A stepped workspace with one middleware and one observer recording what it perceives. */
    private static final class Bench {
        final Workspace ws = Workspace.builder("main").stepped().build();
        final List<String> signals = new ArrayList<>();
        final Map<String, Object> properties = new HashMap<>();
        final AgentId agent;
        final ArtifactId id;
        final MiddlewareArtifact middleware;
        long step;

        Bench(Class<? extends MiddlewareArtifact> type) throws Exception {
            agent = ws.join("robot", new ArtifactObserverAdapter() {
                @Override
                public void focused(ArtifactId a, List<PropertySnapshot> ps) {
                    ps.forEach(p -> properties.put(p.name(), p.values().size() == 1 ? p.value() : p.values()));
                }

                @Override
                public void propertyAdded(ArtifactId a, PropertySnapshot p) {
                    properties.put(p.name(), p.values().size() == 1 ? p.value() : p.values());
                }

                @Override
                public void propertyUpdated(ArtifactId a, PropertySnapshot old, PropertySnapshot now) {
                    properties.put(now.name(), now.values().size() == 1 ? now.value() : now.values());
                }

                @Override
                public void signalled(ArtifactId a, String type, List<Object> args) {
                    signals.add(args.isEmpty() ? type : type + args);
                }
            });
            id = ws.createArtifact("middleware", type.getName(), 0, "lockstep");
            middleware = ws.artifactObject(id, MiddlewareArtifact.class).orElseThrow();
            op("focus", new Object[] {id});
            op("acquireData", new Object[0]);
        }

        OpOutcome op(String name, Object[] args) {
            var outcome = new OpOutcome[1];
            ws.execOp(agent, name.equals("focus") ? OpTarget.any() : OpTarget.id(id), name, args, o -> outcome[0] = o);
            ws.runPending();
            return outcome[0];
        }

        void deliver(SensorInfo... readings) {
            step++;
            op("deliverStep", new Object[] {new StepData(step, step * 40, List.of(readings))});
        }
    }

    private static SensorInfo value(SensorKind kind, double v) {
        return new SensorInfo(kind.id(), v);
    }

    @Test
    void obstacleFromTheLeftRightDifferenceOrAWarningValueAndClearWhenSafe() throws Exception {
        var b = new Bench(ObstacleAvoidanceMiddleware.class);
        b.deliver(value(SensorKind.LEFT_DISTANCE, 150), value(SensorKind.RIGHT_DISTANCE, 20));
        assertEquals(true, b.properties.get("obstacle"), "a difference over 100");
        assertEquals(130.0, ((Number) b.properties.get("delta")).doubleValue());
        b.deliver(value(SensorKind.LEFT_DISTANCE, 50), value(SensorKind.RIGHT_DISTANCE, 40));
        assertEquals(false, b.properties.get("obstacle"), "both safe and close to each other");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 360), value(SensorKind.RIGHT_DISTANCE, 300));
        assertEquals(true, b.properties.get("obstacle"), "a value over the warning threshold");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 250), value(SensorKind.RIGHT_DISTANCE, 240));
        assertEquals(true, b.properties.get("obstacle"), "not yet safe: the obstacle stays");
        assertEquals(true, b.properties.get("connected"));
    }

    @Test
    void theAgentSetsTheLevelsAndTheDifferenceThatSignalAnObstacle() throws Exception {
        var b = new Bench(ObstacleAvoidanceMiddleware.class);
        assertTrue(b.op("obstacleLevels", new Object[] {480.0, 300.0}).succeeded());
        assertTrue(b.op("deltaLimit", new Object[] {150.0}).succeeded());
        b.deliver(value(SensorKind.LEFT_DISTANCE, 150), value(SensorKind.RIGHT_DISTANCE, 20));
        assertEquals(false, b.properties.get("obstacle"), "a difference of 130 is under the limit of 150");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 400), value(SensorKind.RIGHT_DISTANCE, 380));
        assertEquals(false, b.properties.get("obstacle"), "400 is under the warning level of 480");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 200), value(SensorKind.RIGHT_DISTANCE, 30));
        assertEquals(true, b.properties.get("obstacle"), "a difference of 170");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 250), value(SensorKind.RIGHT_DISTANCE, 240));
        assertEquals(false, b.properties.get("obstacle"), "both under the safe level of 300");
        assertTrue(!b.op("deltaLimit", new Object[] {0.0}).succeeded(), "a limit must be positive");
    }

    @Test
    void theAgentSetsTheDifferenceUnderWhichAnObstacleIsClearAgain() throws Exception {
        var b = new Bench(ObstacleAvoidanceMiddleware.class);
        assertTrue(b.op("obstacleLevels", new Object[] {480.0, 300.0}).succeeded());
        assertTrue(b.op("deltaLimit", new Object[] {200.0}).succeeded());
        assertTrue(b.op("deltaClear", new Object[] {75.0}).succeeded());
        b.deliver(value(SensorKind.LEFT_DISTANCE, 250), value(SensorKind.RIGHT_DISTANCE, 30));
        assertEquals(true, b.properties.get("obstacle"), "a difference of 220");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 200), value(SensorKind.RIGHT_DISTANCE, 110));
        assertEquals(true, b.properties.get("obstacle"), "a difference of 90: under half the limit, not under 75");
        b.deliver(value(SensorKind.LEFT_DISTANCE, 150), value(SensorKind.RIGHT_DISTANCE, 100));
        assertEquals(false, b.properties.get("obstacle"), "a difference of 50, both safe");
        assertTrue(!b.op("deltaClear", new Object[] {0.0}).succeeded(), "a level must be positive");
    }

    @Test
    void aRedCylinderAheadIsSignalledOnceAndAGreyObstacleIsAnObstacle() throws Exception {
        var b = new Bench(ObjectPickingMiddleware.class);
        var red = new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), new int[] {90, 90, 90, 200, 40, 30, 90, 90, 90});
        b.deliver(red, value(SensorKind.CENTRAL_DISTANCE, 500));
        b.deliver(red, value(SensorKind.CENTRAL_DISTANCE, 510));
        assertEquals(List.of("cylinderDetected"), b.signals, "signalled once while it stays close");
        var grey = new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), new int[] {90, 90, 90, 120, 110, 100, 90, 90, 90});
        b.deliver(grey, value(SensorKind.CENTRAL_DISTANCE, 100));
        b.deliver(grey, value(SensorKind.CENTRAL_DISTANCE, 500));
        assertEquals(true, b.properties.get("obstacle"));
        assertEquals(List.of("cylinderDetected"), b.signals);
    }

    @Test
    void farCylindersAreSignalledOnlyWhenScanningAtMostOncePerPeriodAndNotInAnIgnoredArea() throws Exception {
        var b = new Bench(NavigationMiddleware.class);
        var image = new SensorInfo(SensorKind.CAMERA_IMAGE.id(), CylinderSightingTest.image(0xC81E1E, 31, 33));
        // at the origin, orientation 0 (facing +x: north vector {1, 0, 0}); the cylinder straight ahead
        var gps = new SensorInfo(SensorKind.GPS.id(), 0.0, 0.0, 0.0);
        var compass = new SensorInfo(SensorKind.COMPASS.id(), 1.0, 0.0, 0.0);
        b.deliver(gps, compass, image);
        assertTrue(b.signals.isEmpty(), "not scanning: " + b.signals);
        b.op("scanForCylinders", new Object[] {400.0, 60.0});
        b.deliver(gps, compass, image);
        b.deliver(gps, compass, image);
        assertEquals(1, b.signals.size(), "at most one per 400 ms: " + b.signals);
        assertTrue(b.signals.get(0).startsWith("cylinderSighted[0.0,"), b.signals.toString());
        for (int i = 0; i < 10; i++) {
            b.deliver(gps, compass, image);
        }
        assertEquals(2, b.signals.size(), "again after 400 ms: " + b.signals);
        b.op("ignoreCylindersNear", new Object[] {0.75, 0.0, 0.2});
        for (int i = 0; i < 20; i++) {
            b.deliver(gps, compass, image);
        }
        assertEquals(2, b.signals.size(), "the cylinder ahead lies in the ignored area: " + b.signals);
        b.op("ignoreCylindersNear", new Object[] {0.0, 0.75, 0.2}); // off to a side: changes nothing
        var other = new Bench(NavigationMiddleware.class);
        other.op("scanForCylinders", new Object[] {400.0, 60.0});
        other.op("ignoreCylindersNear", new Object[] {0.0, 0.75, 0.2});
        other.deliver(gps, compass, image);
        assertEquals(1, other.signals.size(), "an area off the line of sight hides nothing: " + other.signals);
    }

    /** The storage area's pile ahead (the widest run) and a lone cylinder to the left: only every red run shows the lone one. */
    @Test
    void aCylinderBesideAnIgnoredAreaIsSignalledWhenEveryRedRunIsLookedAt() throws Exception {
        int[] framed = CylinderSightingTest.image(0xC81E1E, 30, 34);
        for (int x = 4; x < 6; x++) {
            framed[2 + 3 * 64 + x] = 0xC81E1E;
        }
        var image = new SensorInfo(SensorKind.CAMERA_IMAGE.id(), framed);
        var gps = new SensorInfo(SensorKind.GPS.id(), 0.0, 0.0, 0.0);
        var compass = new SensorInfo(SensorKind.COMPASS.id(), 1.0, 0.0, 0.0);
        var widest = new Bench(NavigationMiddleware.class);
        widest.op("scanForCylinders", new Object[] {400.0, 60.0});
        widest.op("ignoreCylindersNear", new Object[] {0.35, 0.0, 0.1});
        widest.deliver(gps, compass, image);
        assertTrue(widest.signals.isEmpty(), "the widest run is the pile's: " + widest.signals);
        var every = new Bench(NavigationMiddleware.class);
        every.op("scanForCylinders", new Object[] {400.0, 60.0});
        every.op("ignoreCylindersNear", new Object[] {0.35, 0.0, 0.1});
        every.op("sightEveryRedRun", new Object[0]);
        every.deliver(gps, compass, image);
        assertEquals(1, every.signals.size(), every.signals.toString());
        assertTrue(every.signals.get(0).startsWith("cylinderSighted[-25."), "the lone one, to the left: " + every.signals);
    }

    @Test
    void exploreTurnNeedsOdometryThenProposesATurnTimedForTheWheelSpeed() throws Exception {
        var b = new Bench(ObstacleAvoidanceMiddleware.class);
        var side = new OpFeedbackParam<String>();
        var ms = new OpFeedbackParam<Double>();
        assertTrue(!b.op("exploreTurn", new Object[] {100.0, side, ms}).succeeded(), "no odometry yet");
        b.op("odometry", new Object[] {0.001, 0.09});
        // a straight run ahead: the floor ahead is known, so the proposal is a turn
        for (int i = 0; i < 50; i++) {
            b.deliver(new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {100, 100}));
        }
        assertTrue(b.op("exploreTurn", new Object[] {100.0, side, ms}).succeeded());
        assertTrue(side.get().equals("left") || side.get().equals("right"), side.get());
        // at 100 the MyBot turns 127 degrees a second: a turn of 30 to 180 degrees takes 0.2 to 1.5 s
        assertTrue(ms.get() >= 200 && ms.get() <= 1500, ms.get() + " ms");
    }

    @Test
    void wallsReadByTheFrontSensorsEndTheFloorAheadOnceTheAgentAsksForTheirMarks() throws Exception {
        var side = new OpFeedbackParam<String>();
        var ms = new OpFeedbackParam<Double>();
        String[] turns = new String[2];
        for (int marks = 0; marks < 2; marks++) {
            var b = new Bench(ObstacleAvoidanceMiddleware.class);
            assertFalse(b.op("markWalls", new Object[] {200.0}).succeeded(), "no odometry yet");
            b.op("odometry", new Object[] {0.001, 0.09});
            b.op("exploreHorizon", new Object[] {0.6});
            assertFalse(b.op("markWalls", new Object[] {0.0}).succeeded(), "a level under 1");
            if (marks == 1) {
                assertTrue(b.op("markWalls", new Object[] {200.0}).succeeded());
            }
            // a turn of 60 degrees to the right on the spot (towards the most new floor, unmarked),
            // then standing still with a wall 12 cm ahead of both sensors: readings of 200, under
            // every obstacle level, so no obstacle(true) marks it
            for (int i = 0; i < 12; i++) {
                b.deliver(new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {100, -100}));
            }
            for (int i = 0; i < 5; i++) {
                b.deliver(value(SensorKind.LEFT_DISTANCE, 200), value(SensorKind.RIGHT_DISTANCE, 200),
                        new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {0, 0}));
            }
            assertEquals(false, b.properties.get("obstacle"));
            assertTrue(b.op("exploreTurn", new Object[] {100.0, side, ms}).succeeded());
            turns[marks] = side.get() + " " + ms.get();
            if (marks == 1) {
                // 30 degrees take 236 ms: the wall's marks end the floor ahead and a little to either side
                assertTrue(ms.get() > 240, "the wall ahead ends the floor there: a turn away, got " + turns[1]);
            }
        }
        assertFalse(turns[0].equals(turns[1]), "the same turn with and without the marks: " + turns[0]);
        assertEquals(0.12, ObstacleAvoidanceMiddleware.rangeOf(200), 1e-9);
        assertEquals(0.065, ObstacleAvoidanceMiddleware.rangeOf(415), 1e-9);
        assertEquals(0.20, ObstacleAvoidanceMiddleware.rangeOf(0), 1e-9);
    }

    @Test
    void walledInOnlyOnceBothSensorsSawAWallForTheSpanDriven() throws Exception {
        var b = new Bench(ObstacleAvoidanceMiddleware.class);
        assertFalse(b.op("corridorSpan", new Object[] {15.0, 0.15}).succeeded(), "no odometry yet");
        b.op("odometry", new Object[] {0.001, 0.09});
        assertFalse(b.op("corridorSpan", new Object[] {15.0, -1.0}).succeeded(), "a negative span");
        assertTrue(b.op("corridorSpan", new Object[] {15.0, 0.15}).succeeded());
        assertEquals(false, b.properties.get("walledIn"));
        // 4 mm a step at 100: a wall on each side for 20 steps (8 cm, two boxes side by side), then
        // one side clear, then both walls again for 50 steps (20 cm, a passage)
        int[] firstWalled = {-1};
        int[] rights = new int[80];
        java.util.Arrays.fill(rights, 60);
        rights[20] = 0;
        for (int i = 0; i < rights.length; i++) {
            b.deliver(value(SensorKind.LEFT_DISTANCE, 80), value(SensorKind.RIGHT_DISTANCE, rights[i]),
                    new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {100, 100}));
            if (i < 21) {
                assertEquals(false, b.properties.get("walledIn"), "step " + i);
            } else if (firstWalled[0] < 0 && Boolean.TRUE.equals(b.properties.get("walledIn"))) {
                firstWalled[0] = i;
            }
        }
        // 15 cm after the run began at step 21: 37-38 steps of 4 mm
        assertTrue(firstWalled[0] >= 57 && firstWalled[0] <= 61, "walled in from step " + firstWalled[0]);
        b.deliver(value(SensorKind.LEFT_DISTANCE, 10), value(SensorKind.RIGHT_DISTANCE, 60),
                new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {100, 100}));
        assertEquals(false, b.properties.get("walledIn"), "one side under the level");
        assertFalse(new Bench(ObstacleAvoidanceMiddleware.class).properties.containsKey("walledIn"),
                "no walledIn percept unless the agent asks for it");
    }

    @Test
    void freshCellsCountsNewFloorOfTheLastWindowAndVisitedAreaAllOfIt() throws Exception {
        var b = new Bench(ObstacleAvoidanceMiddleware.class);
        var cells = new OpFeedbackParam<Double>();
        var area = new OpFeedbackParam<Double>();
        assertTrue(!b.op("freshCells", new Object[] {30000.0, cells}).succeeded(), "no odometry yet");
        assertTrue(!b.op("visitedArea", new Object[] {area}).succeeded(), "no odometry yet");
        b.op("odometry", new Object[] {0.001, 0.09});
        // 10 s straight at 0.1 m/s (a reading every 40 ms): 1 m, ten new cells after the start's
        for (int i = 0; i < 250; i++) {
            b.deliver(new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {100, 100}));
        }
        // then 10 s on the spot: nothing new
        for (int i = 0; i < 250; i++) {
            b.deliver(new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {100, -100}));
        }
        assertTrue(b.op("freshCells", new Object[] {5000.0, cells}).succeeded());
        assertEquals(0.0, cells.get(), "no new floor in the last 5 s");
        assertTrue(b.op("freshCells", new Object[] {30000.0, cells}).succeeded());
        assertEquals(10.0, cells.get(), 1.0, "the metre driven");
        assertTrue(b.op("visitedArea", new Object[] {area}).succeeded());
        assertEquals(0.11, area.get(), 0.011, "eleven cells of 0.01 m2");
        // no obstacle met: open floor beside the metre crossed is a frontier, a turn and a short leg away
        var side = new OpFeedbackParam<String>();
        var ms = new OpFeedbackParam<Double>();
        var metres = new OpFeedbackParam<Double>();
        assertTrue(b.op("frontierTurn", new Object[] {100.0, side, ms, metres}).succeeded());
        assertTrue(side.get().equals("left") || side.get().equals("right"), side.get());
        assertTrue(metres.get() > 0 && metres.get() <= 0.5, metres.get() + " m");
    }

    @Test
    void gripForceMeansCaughtAndAFallIsSignalledForAPickedCylinder() throws Exception {
        var b = new Bench(ObjectPickingMiddleware.class);
        b.deliver(value(SensorKind.GRIP_FORCE, -40), new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[] {1, 1}),
                value(SensorKind.GRIP_PRESENCE, 1));
        assertEquals(true, b.properties.get("caught"));
        assertEquals(false, b.properties.get("picked"), "the arm is still down");
        b.deliver(value(SensorKind.GRIP_FORCE, -40), new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[] {0, 1}),
                value(SensorKind.GRIP_PRESENCE, 1));
        assertEquals(true, b.properties.get("picked"));
        b.deliver(value(SensorKind.GRIP_FORCE, 0), value(SensorKind.GRIP_PRESENCE, 0));
        assertTrue(b.signals.contains("fallen"), b.signals.toString());
        assertEquals(false, b.properties.get("picked"));
    }

    @Test
    void objectPickingPublishesLocationAndOrientationOnlyOnceAsked() throws Exception {
        var b = new Bench(ObjectPickingMiddleware.class);
        var gps = new SensorInfo(SensorKind.GPS.id(), 0.256, 0.0, -0.301);
        var compass = new SensorInfo(SensorKind.COMPASS.id(), Math.cos(Math.toRadians(90)), 0.0, -Math.sin(Math.toRadians(90)));
        b.deliver(gps, compass);
        assertFalse(b.properties.containsKey("location"), b.properties.toString());
        assertTrue(b.op("publishLocation", new Object[0]).succeeded());
        b.deliver(gps, compass);
        assertEquals(List.of(0.25, 0.0, -0.31), b.properties.get("location"), "truncated to centimetres");
        assertEquals(90.0, ((Number) b.properties.get("orientation")).doubleValue(), 0.05);
    }

    @Test
    void gpsCompassHeadingsAndTheTargetPoint() throws Exception {
        var b = new Bench(NavigationMiddleware.class);
        b.op("setUpTargetPoint", new Object[] {0.41, 0.0, -0.41});
        // compass north vector {cos b, 0, -sin b} for a bearing of 90 degrees (east)
        b.deliver(new SensorInfo(SensorKind.GPS.id(), 0.0, 0.0, 0.0),
                new SensorInfo(SensorKind.COMPASS.id(), Math.cos(Math.toRadians(90)), 0.0, -Math.sin(Math.toRadians(90))));
        assertEquals(90.0, ((Number) b.properties.get("orientation")).doubleValue(), 0.05);
        var desired = new OpFeedbackParam<Double>();
        var outcome = b.op("computeAngle", new Object[] {0.0, 0.0, 0.41, -0.41, desired});
        assertTrue(outcome.succeeded());
        assertEquals(315.0, desired.get(), 0.01, "north-west of the robot: the storage point of Appendix B");
        b.deliver(new SensorInfo(SensorKind.GPS.id(), 0.40, 0.0, -0.40));
        assertTrue(b.signals.contains("targetReached"), b.signals.toString());
        assertTrue(b.signals.contains("noAccess"), "near the storage area: " + b.signals);
    }

    @Test
    void whatTheDistanceSensorsSeeIsMappedAndTheRouteGoesRoundIt() throws Exception {
        var b = new Bench(NavigationMiddleware.class);
        assertTrue(b.op("routeMap", new Object[] {2.0, 2.0, 60_000.0}).succeeded());
        assertTrue(!b.op("routeMap", new Object[] {0.0, 2.0, 60_000.0}).succeeded(), "an arena has a size");
        // at the centre, heading 90 degrees (towards +z): the right-hand sensor looks towards -x
        var gps = new SensorInfo(SensorKind.GPS.id(), 0.0, 0.0, 0.0);
        var compass = new SensorInfo(SensorKind.COMPASS.id(), Math.cos(Math.toRadians(90)), 0.0, -Math.sin(Math.toRadians(90)));
        b.deliver(gps, compass);
        var wx = new OpFeedbackParam<Double>();
        var wz = new OpFeedbackParam<Double>();
        assertTrue(b.op("routeTo", new Object[] {-0.3, 0.0, wx, wz}).succeeded());
        assertEquals(List.of(-0.3, 0.0, 0), b.properties.get("route"), "nothing seen: the straight way");
        // a wall 2.5 cm from the right-hand sensor (350), seen while the robot turns it past (the whole wall, z -0.1..0.1)
        for (double z = -0.1; z <= 0.1; z += 0.01) {
            b.deliver(new SensorInfo(SensorKind.GPS.id(), 0.0, 0.0, z), compass, value(SensorKind.RIGHT_DISTANCE, 350));
        }
        b.deliver(gps, compass);
        assertTrue(b.op("routeTo", new Object[] {-0.3, 0.0, wx, wz}).succeeded());
        assertTrue(wx.get() > -0.04 && Math.abs(wz.get()) > 0.005, "towards an end of the wall seen at x = -0.05, not through it: "
                + wx.get() + ", " + wz.get());
        assertTrue((Integer) ((List<?>) b.properties.get("route")).get(2) > 0);
    }

    @Test
    void theTrailKeptGivesTheWayBackTheRobotCame() throws Exception {
        var b = new Bench(NavigationMiddleware.class);
        var wx = new OpFeedbackParam<Double>();
        var wz = new OpFeedbackParam<Double>();
        assertTrue(b.op("trailTo", new Object[] {-0.5, 0.0, wx, wz}).succeeded());
        assertEquals(List.of(-0.5, 0.0), List.of(wx.get(), wz.get()), "no trail kept: the target");
        assertTrue(b.op("keepTrail", new Object[] {}).succeeded());
        // out from (-0.5, 0) north to (-0.5, 0.5), east to (0, 0.5), south to (0, 0)
        double[][] way = {{-0.5, 0}, {-0.5, 0.5}, {0, 0.5}, {0, 0}};
        for (int i = 1; i < way.length; i++) {
            for (double f = 0; f <= 1; f += 0.02) {
                b.deliver(new SensorInfo(SensorKind.GPS.id(), way[i - 1][0] + f * (way[i][0] - way[i - 1][0]), 0.0,
                        way[i - 1][1] + f * (way[i][1] - way[i - 1][1])));
            }
        }
        assertTrue(b.op("trailTo", new Object[] {-0.5, 0.0, wx, wz}).succeeded());
        assertTrue(Math.abs(wx.get()) < 0.01 && wz.get() > 0.05, "back north along the way out, not west across: " + wx.get() + ", " + wz.get());
    }

    @Test
    void lowBatterySignalsAndCommandsQueueInLockstep() throws Exception {
        var b = new Bench(SuspendResumeMiddleware.class);
        b.deliver(value(SensorKind.BATTERY, 500));
        assertTrue(b.signals.isEmpty());
        b.deliver(value(SensorKind.BATTERY, 479));
        assertEquals(List.of("lowBattery"), b.signals);
        b.op("stop", new Object[0]);
        b.op("setSpeeds", new Object[] {25.0, -10.0});
        assertEquals(List.of(Command.stop(), Command.setSpeeds(25, -10)), b.middleware.takeCommands());
        assertEquals(List.of(), b.middleware.takeCommands(), "taken once");
    }

    /** {@code mark} records the robot's (x, z), {@code mark(X, Y, Z)} the point given: where the low-battery episode began. */
    @Test
    void markRecordsTheRobotsPlaceOrThePointGiven() throws Exception {
        var b = new Bench(SuspendResumeMiddleware.class);
        b.deliver(new SensorInfo(SensorKind.GPS.id(), 0.4, 0.0, -0.3));
        assertTrue(b.op("mark", new Object[0]).succeeded());
        double[] here = ((SuspendResumeMiddleware) b.middleware).marked();
        assertEquals(0.4, here[0], 1e-9);
        assertEquals(-0.3, here[1], 1e-9);
        assertTrue(b.op("mark", new Object[] {-0.2, 0.0, 0.7}).succeeded());
        double[] given = ((SuspendResumeMiddleware) b.middleware).marked();
        assertEquals(-0.2, given[0], 1e-9);
        assertEquals(0.7, given[1], 1e-9);
    }
}
