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
    void anEpisodeBegunLateIsNotYetDue() {
        var done = new BatteryEpisodes.Episode(100, new Vec2(0, 0), 150, 170);
        var open = new BatteryEpisodes.Episode(300, new Vec2(0, 0), Double.NaN, Double.NaN);
        var late = new BatteryEpisodes.Episode(500, new Vec2(0, 0), Double.NaN, Double.NaN);
        assertEquals(2, SuccessCriteria.episodesDue(List.of(done, open, late), 600));
        assertEquals(3, SuccessCriteria.episodesDue(List.of(done, open, late), 700));
    }

    private static SuccessCriteria.TeamFigures team(int deliveries, List<Double> contacts, int emptied, int doubleClaims, double wait) {
        return new SuccessCriteria.TeamFigures(600, 12, deliveries, contacts, emptied, doubleClaims, wait);
    }

    @Test
    void aTeamNeedsTwoDeliveriesPerRobotCountedTogether() {
        assertTrue(SuccessCriteria.judgeTeam(team(4, List.of(0.5, 1.9), 0, 0, 60)).success(), "4 for two robots, whoever made them");
        assertEquals("3 team deliveries (< 4)", SuccessCriteria.judgeTeam(team(3, List.of(0.0, 0.0), 0, 0, 0)).reason());
        var eight = new SuccessCriteria.TeamFigures(600, 12, 12, List.of(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), 0, 0, 0);
        assertTrue(SuccessCriteria.judgeTeam(eight).success(), "never more than the world's cylinders");
    }

    @Test
    void aTeamFailsOnContactEmptyBatteriesDoubleClaimsAndStarvation() {
        var v = SuccessCriteria.judgeTeam(team(8, List.of(0.1, 2.0, 0.3), 1, 2, 61));
        assertFalse(v.success());
        assertEquals("robot 2: contact 2.0 s (>= 2 s); 1 battery empty; 2 double claims; waited 61 s for the charger (> 60 s)", v.reason());
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
