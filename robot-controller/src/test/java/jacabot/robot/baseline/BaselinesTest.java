package jacabot.robot.baseline;
import jacabot.robot.Experiment;
import jacabot.robot.baseline.BaselineRunner.BaselineRun;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.geom.Pose;
import jacabot.sim.io.WorldFileException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Each baseline achieves its experiment's task in its world file, with fixed seeds, in bounded simulated time. */
class BaselinesTest {
    static Path worlds() {
        String root = System.getProperty("jacabot.rootDir");
        return (root == null ? Path.of("..") : Path.of(root)).resolve("worlds");
    }

    static RunSummary run(Experiment e, long seed, double seconds) throws WorldFileException {
        return BaselineRunner.run(e.worldFile(worlds()), e, seed, seconds);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2})
    void obstacleAvoidanceKeepsMovingOverTheArenaWithoutSustainedContact(long seed) throws WorldFileException {
        RunSummary s = run(Experiment.OBSTACLE_AVOIDANCE, seed, 600);
        assertEquals(600, s.duration(), 1e-9);
        assertTrue(s.distance() > 15, s.toText());
        assertTrue(s.coverage() >= 0.6, s.toText());
        assertTrue(s.contactTime() < 10, s.toText());
        assertTrue(s.longestContact() < 2, s.toText());
        assertTrue(s.eventLog().contains("world: removed 'box1'"), "the scripted events ran: " + s.eventLog());
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 3})
    void objectPickingLiftsTheRedCylinder(long seed) throws WorldFileException {
        RunSummary s = run(Experiment.OBJECT_PICKING, seed, 90);
        assertEquals(1, s.picks(), s.eventLog());
        assertTrue(s.pickTimes().get(0) < 60, s.toText());
        assertEquals(0, s.lost(), s.eventLog());
        assertTrue(s.eventLog().contains("controller: Picking ok"), s.eventLog());
    }

    @Test
    void aCylinderKnockedOutOfTheGripperStopsTheRobotForGood() throws WorldFileException {
        Experiment e = Experiment.OBJECT_PICKING;
        SimWorld world = BaselineRunner.load(e.worldFile(worlds()), 1);
        RunRecorder rec = RunRecorder.attach(world, e.robot());
        world.addListener(new WorldListener() {
            private int carrying;

            @Override
            public void controlStepEnded(long timeMs) {
                // Knocked out 4 s after the grasp, once the arm is up and the robot wanders on.
                if (world.supervisor().carried(e.robot()) != null && ++carrying == 100) {
                    world.supervisor().knockCarried(e.robot());
                }
            }
        });
        BaselineRunner.create(e, world, 1, rec::note).runFor(60);
        RunSummary s = rec.summary(BaselineRunner.CONTROLLER);
        assertEquals(1, s.lost(), s.eventLog());
        assertTrue(s.eventLog().contains("controller: Cylinder has fallen. Anybody retrieve it."), s.eventLog());
        List<Pose> path = rec.trajectory();
        assertEquals(path.get(path.size() - 1), path.get(path.size() - 10), "it stopped");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2})
    void navigationDeliversBothCylindersAndNeverComesBackEmpty(long seed) throws WorldFileException {
        RunSummary s = run(Experiment.NAVIGATION, seed, 400);
        assertEquals(2, s.deliveries(), s.eventLog());
        assertEquals(0, s.storageEntriesEmpty(), s.eventLog());
        assertEquals(0, s.lost(), s.eventLog());
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 3})
    void suspendResumeRechargesReturnsToTheMarkAndCarriesOn(long seed) throws WorldFileException {
        Experiment e = Experiment.SUSPEND_RESUME;
        BaselineRun run = BaselineRunner.execute(e.worldFile(worlds()), e, seed, 400);
        RunSummary s = run.summary();
        assertFalse(s.batteryEmptied(), s.toText());
        assertTrue(s.batteryMin() > 300, s.toText());
        assertTrue(s.chargerVisits() >= 1, s.toText());
        assertTrue(s.deliveries() >= 2, s.eventLog());
        assertEquals(0, s.storageEntriesEmpty(), s.eventLog());
        List<SuspendResumeBaseline.Suspension> done = ((SuspendResumeBaseline) run.controller()).suspensions();
        assertFalse(done.isEmpty(), s.eventLog());
        for (SuspendResumeBaseline.Suspension x : done) {
            assertTrue(x.back().distanceTo(x.mark()) <= 0.06, x.toString());
            assertTrue(Math.abs(KheperaIo.gap(x.markHeading(), x.backHeading())) < 1, x.toString());
        }
    }

    @Test
    void aDeliveryInterruptedByALowBatteryIsCompletedAfterRecharging() throws WorldFileException {
        Experiment e = Experiment.SUSPEND_RESUME;
        SimWorld world = BaselineRunner.load(e.worldFile(worlds()), 1);
        world.supervisor().setBattery(e.robot(), 1000);
        RunRecorder rec = RunRecorder.attach(world, e.robot());
        world.addListener(new WorldListener() {
            private boolean drained;

            @Override
            public void controlStepEnded(long timeMs) {
                // Five seconds into the first delivery, the battery drops under the threshold.
                if (!drained && !rec.summary("").pickTimes().isEmpty() && timeMs / 1000.0 > rec.summary("").pickTimes().get(0) + 5) {
                    drained = true;
                    world.supervisor().setBattery(e.robot(), 470);
                }
            }
        });
        SuspendResumeBaseline c = (SuspendResumeBaseline) BaselineRunner.create(e, world, 1, rec::note);
        c.runFor(200);
        RunSummary s = rec.summary(BaselineRunner.CONTROLLER);
        assertEquals(1, c.suspensions().size(), s.eventLog());
        SuspendResumeBaseline.Suspension x = c.suspensions().get(0);
        assertTrue(x.lowAt() > s.pickTimes().get(0), s.eventLog());
        assertTrue(s.deliveryTimes().get(0) > x.resumedAt(), "delivered after resuming: " + s.eventLog());
        assertTrue(s.eventLog().contains("controller: Restored: resuming the delivery"), s.eventLog());
        assertEquals(1, s.chargerVisits(), s.eventLog());
        assertTrue(x.back().distanceTo(x.mark()) <= 0.06, x.toString());
    }

    @Test
    void twoRunsWithTheSameSeedGiveTheSameEventLogAndSummary() throws WorldFileException {
        RunSummary a = run(Experiment.NAVIGATION, 3, 60), b = run(Experiment.NAVIGATION, 3, 60);
        assertTrue(a.events().size() > 5, a.eventLog());
        assertEquals(a.eventLog(), b.eventLog());
        assertEquals(a.toJson(), b.toJson());
        RunSummary c = run(Experiment.NAVIGATION, 4, 60);
        assertFalse(a.toJson().equals(c.toJson()), "another seed, another run");
    }
}
