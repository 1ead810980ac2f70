package jacabot.app.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.sim.geom.Vec2;
import java.util.List;
import org.junit.jupiter.api.Test;

class SuccessCriteriaTest {
    private static SuccessCriteria.Figures figures(double contact, double coverage, int picks, int deliveries, int empty,
            boolean emptied, int episodes, int completed) {
        return new SuccessCriteria.Figures(600, contact, coverage, picks, deliveries, empty, emptied, episodes, completed);
    }

    @Test
    void obstacleAvoidanceNeedsLittleContactAndHalfTheArena() {
        assertTrue(SuccessCriteria.judge(Experiment.OBSTACLE_AVOIDANCE, figures(1.9, 0.5, 0, 0, 0, false, 0, 0)).success());
        var v = SuccessCriteria.judge(Experiment.OBSTACLE_AVOIDANCE, figures(2.0, 0.49, 0, 0, 0, false, 0, 0));
        assertFalse(v.success());
        assertEquals("contact 2.0 s (>= 2 s); coverage 49% (< 50%)", v.reason());
    }

    @Test
    void pickingNeedsOnePick() {
        assertTrue(SuccessCriteria.judge(Experiment.OBJECT_PICKING, figures(30, 0, 1, 0, 0, false, 0, 0)).success());
        assertEquals("no cylinder picked", SuccessCriteria.judge(Experiment.OBJECT_PICKING, figures(0, 1, 0, 0, 0, false, 0, 0)).reason());
    }

    @Test
    void navigationNeedsTwoDeliveriesAndNoEmptyEntry() {
        assertTrue(SuccessCriteria.judge(Experiment.NAVIGATION, figures(9, 0, 2, 2, 0, false, 0, 0)).success());
        assertEquals("1 delivery (< 2); 1 storage entry without a cylinder",
                SuccessCriteria.judge(Experiment.NAVIGATION, figures(0, 0, 3, 1, 1, false, 0, 0)).reason());
    }

    @Test
    void suspendResumeNeedsBatteryADeliveryAndCompletedEpisodes() {
        assertTrue(SuccessCriteria.judge(Experiment.SUSPEND_RESUME, figures(9, 0, 1, 1, 3, false, 2, 2)).success());
        assertEquals("battery empty; no delivery; 1 of 2 low-battery episodes without recharge and return",
                SuccessCriteria.judge(Experiment.SUSPEND_RESUME, figures(0, 0, 0, 0, 0, true, 2, 1)).reason());
    }

    @Test
    void tidyUpNeedsEveryCylinderStoredAndTheRobotOnTheCharger() {
        assertTrue(SuccessCriteria.judge(Experiment.TIDY_UP,
                new SuccessCriteria.Figures(600, 0, 0, 4, 4, 0, false, 1, 1, 4, 4, true)).success());
        assertEquals("battery empty; 3 of 4 cylinders in the storage area; not parked on the charger",
                SuccessCriteria.judge(Experiment.TIDY_UP, new SuccessCriteria.Figures(600, 0, 0, 4, 4, 0, true, 1, 1, 4, 3, false)).reason());
        // the thesis' experiments read no end state: their figures leave it empty, and tidy-up fails on them
        assertFalse(SuccessCriteria.judge(Experiment.TIDY_UP, figures(0, 0, 2, 2, 0, false, 0, 0)).success());
    }

    @Test
    void otherDurationsScaleWhatIsARateAndShortRunsCarryACaveat() {
        // deliveries: 2 per 10 minutes, at least 1; contact: 2 s per 10 minutes, never under 2 s
        assertEquals(1, SuccessCriteria.minDeliveries(60));
        assertEquals(2, SuccessCriteria.minDeliveries(600));
        assertEquals(12, SuccessCriteria.minDeliveries(3600));
        assertEquals(2.0, SuccessCriteria.maxContact(60));
        assertEquals(12.0, SuccessCriteria.maxContact(3600));
        var oneMinute = new SuccessCriteria.Figures(60, 0, 0, 1, 1, 0, false, 0, 0);
        assertTrue(SuccessCriteria.judge(Experiment.NAVIGATION, oneMinute).success(), "one delivery in one minute");
        var hour = new SuccessCriteria.Figures(3600, 0, 0, 3, 3, 0, false, 0, 0);
        assertEquals("3 deliveries (< 12)", SuccessCriteria.judge(Experiment.NAVIGATION, hour).reason());
        assertTrue(SuccessCriteria.caveat(60).orElseThrow().startsWith("runs of 60 s are judged by criteria made for 10 simulated minutes"));
        assertTrue(SuccessCriteria.caveat(600).isEmpty());
        // the report of a short sweep says so
        var run = new RunOutcome(Experiment.NAVIGATION, "w", "agent", 1, RunOutcome.OK, true, "", 60, 1, oneMinute, 0, 0);
        assertTrue(SweepReport.markdown(List.of(run), null).contains("**Note:** runs of 60 s are judged by criteria made for 10"));
    }

    @Test
    void anEpisodeBegunLateIsNotYetDue() {
        var done = new BatteryEpisodes.Episode(100, new Vec2(0, 0), 150, 170);
        var open = new BatteryEpisodes.Episode(300, new Vec2(0, 0), Double.NaN, Double.NaN);
        var late = new BatteryEpisodes.Episode(500, new Vec2(0, 0), Double.NaN, Double.NaN);
        assertEquals(2, SuccessCriteria.episodesDue(List.of(done, open, late), 600));
        assertEquals(3, SuccessCriteria.episodesDue(List.of(done, open, late), 700));
    }

    private static SuccessCriteria.TeamFigures team(int deliveries, List<Double> contacts, int emptied, int doubleClaims, double wait) {
        // contact with walls is the one-robot experiments' affair: 9 s of it changes nothing here
        List<Double> all = contacts.stream().map(c -> c + 9).toList();
        return new SuccessCriteria.TeamFigures(600, 12, deliveries, all, contacts, emptied, doubleClaims, wait);
    }

    @Test
    void aTeamNeedsTwoDeliveriesPerRobotCountedTogether() {
        assertTrue(SuccessCriteria.judgeTeam(team(4, List.of(0.5, 1.9), 0, 0, 60)).success(), "4 for two robots, whoever made them");
        assertEquals("3 team deliveries (< 4)", SuccessCriteria.judgeTeam(team(3, List.of(0.0, 0.0), 0, 0, 0)).reason());
        List<Double> none = List.of(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        var eight = new SuccessCriteria.TeamFigures(600, 12, 12, none, none, 0, 0, 0);
        assertTrue(SuccessCriteria.judgeTeam(eight).success(), "never more than the world's cylinders");
    }

    @Test
    void aTeamFailsOnContactEmptyBatteriesDoubleClaimsAndStarvation() {
        var v = SuccessCriteria.judgeTeam(team(8, List.of(0.1, 2.0, 0.3), 1, 2, 61));
        assertFalse(v.success());
        assertEquals("robot 2: contact with robots 2.0 s (>= 2 s); 1 battery empty; 2 double claims; waited 61 s for the charger (> 60 s)", v.reason());
    }

    @Test
    void teamsShouldScaleAlmostLinearly() {
        assertEquals(1.0, SuccessCriteria.scalingTarget(1));
        assertEquals(1.7, SuccessCriteria.scalingTarget(2), 1e-12);
        assertEquals(3.0, SuccessCriteria.scalingTarget(4), 1e-12);
        assertEquals(2.4, SuccessCriteria.scalingTarget(3), 1e-12);
        assertEquals(6.0, SuccessCriteria.scalingTarget(8), 1e-12);
    }
}
