package jacabot.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.device.Camera;
import jacabot.sim.device.DistanceSensor;
import jacabot.sim.device.Section;
import jacabot.sim.geom.Rgb;
import jacabot.sim.robot.Robot;
import jacabot.sim.robot.RobotModel;
import org.junit.jupiter.api.Test;

/**
 * Several robots in one world (a team, thesis Chapter 6): each robot's infra-red sensors see the
 * others as obstacles, its camera sees them in their own colour (not red, so never taken for a
 * cylinder), and each robot counts its own contacts, with the others too.
 */
class TeamWorldTest {
    /** Kheperas "a" at (0, 0) facing north and "b" at (x, z) with the given heading; "c" far off in a corner. */
    private static SimWorld team(double bx, double bz, double bHeading, String members) {
        String robots = "\"robots\": ["
                + "{\"name\": \"a\", \"model\": \"khepera\", \"x\": 0, \"z\": 0, \"heading\": 0},"
                + "{\"name\": \"b\", \"model\": \"khepera\", \"x\": " + bx + ", \"z\": " + bz + ", \"heading\": " + bHeading + "},"
                + "{\"name\": \"c\", \"model\": \"khepera\", \"x\": -0.4, \"z\": -0.4, \"heading\": 0}]";
        return TestWorlds.world(members.isBlank() ? robots : robots + ", " + members);
    }

    /** The thesis' red test (Chapter 4 §2.2: red over twice green and twice blue), and the middleware's own: bright enough. */
    private static boolean isRed(int r, int g, int b) {
        return r > 40 && r > 2 * g && r > 2 * b;
    }

    @Test
    void aRobotTwoCentimetresAheadIsAnObstacleToTheFrontSensor() {
        double rims = 2 * RobotModel.KHEPERA.radius();
        SimWorld w = team(rims + 0.02, 0, 180, "");
        DistanceSensor front = w.robot("a").getDistanceSensor("front");
        DistanceSensor hisFront = w.robot("b").getDistanceSensor("front");
        DistanceSensor farFront = w.robot("c").getDistanceSensor("front");
        front.enable(40);
        hisFront.enable(40);
        farFront.enable(40);
        w.step();
        assertTrue(front.getValue() > 350, "a sees b as an obstacle (> 350), read " + front.getValue());
        assertEquals(front.getValue(), hisFront.getValue(), 1e-9, "face to face, each reads the other alike");
        assertEquals(0.0, farFront.getValue(), "c sees nothing");
    }

    @Test
    void aRobotAlongsideIsSeenByTheSideSensorAndNotByTheOtherSide() {
        double rims = 2 * RobotModel.KHEPERA.radius();
        SimWorld w = team(0, rims + 0.02, 0, ""); // b 2 cm east of a: on a's right
        Robot a = w.robot("a");
        a.getDistanceSensor("right").enable(40);
        a.getDistanceSensor("left").enable(40);
        w.step();
        assertTrue(a.getDistanceSensor("right").getValue() > 350, "right " + a.getDistanceSensor("right").getValue());
        assertEquals(0.0, a.getDistanceSensor("left").getValue());
    }

    @Test
    void theCameraSeesAnotherRobotInItsColourNeverAsRed() {
        SimWorld w = team(0.25, 0, 90, "\"cylinders\": [{\"id\": \"red1\", \"x\": 0.15, \"z\": 0.06}]");
        Camera cam = w.robot("a").getCamera("camera");
        cam.enable(40);
        w.step();
        int[] image = cam.getImage();
        Rgb shell = RobotModel.KHEPERA.color();
        int robotPixels = 0, redPixels = 0;
        for (int y = 0; y < cam.getHeight(); y++) {
            for (int x = 0; x < cam.getWidth(); x++) {
                int r = Camera.imageGetRed(image, cam.getWidth(), x, y), g = Camera.imageGetGreen(image, cam.getWidth(), x, y),
                        b = Camera.imageGetBlue(image, cam.getWidth(), x, y);
                if (new Rgb(r, g, b).equals(shell)) {
                    robotPixels++;
                    assertTrue(x > 20 && x < 42, "b stands straight ahead: the centre columns, not column " + x);
                }
                if (isRed(r, g, b)) {
                    redPixels++;
                    assertTrue(x >= 42, "the cylinder stands to the right: column " + x);
                }
            }
        }
        assertTrue(robotPixels > 0, "b is in the image");
        assertTrue(redPixels > 0, "the cylinder is in the image");
        Rgb centre = cam.getSectionLevels(Section.CENTRE);
        assertFalse(isRed(centre.red(), centre.green(), centre.blue()), "a robot ahead is not a red cylinder: " + centre);
    }

    @Test
    void eachRobotCountsItsOwnContactsWithTheOthers() {
        double rims = 2 * RobotModel.KHEPERA.radius();
        SimWorld w = team(rims + 0.01, 0, 180, "");
        w.robot("a").setSpeeds(50, 50);
        w.robot("b").setSpeeds(50, 50);
        for (int i = 0; i < 50; i++) { // 2 s pushing head on
            w.step();
        }
        assertTrue(w.robot("a").contactTime() > 1.5, "a " + w.robot("a").contactTime());
        assertTrue(w.robot("b").contactTime() > 1.5, "b " + w.robot("b").contactTime());
        assertEquals(w.robot("a").contactTime(), w.robot("a").robotContactTime(), "all of a's contact was with b");
        assertEquals(w.robot("b").contactTime(), w.robot("b").robotContactTime());
        assertEquals(0.0, w.robot("c").contactTime(), "c touched nothing");
        w.robot("c").setSpeeds(-50, -50); // backwards into the wall 10 cm behind it
        for (int i = 0; i < 150; i++) {
            w.step();
        }
        assertTrue(w.robot("c").contactTime() > 1, "c pushed against the wall: " + w.robot("c").contactTime());
        assertEquals(0.0, w.robot("c").robotContactTime(), "a wall is no robot");
    }
}
