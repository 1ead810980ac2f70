package jacabot.sim.device;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.geom.Rgb;
import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * The Khepera's camera (64×8, 60°, lens at the front rim 2.5 cm high) and a red cylinder (radius
 * 1.25 cm, 4 cm high) 6 cm from the lens: seen under ±12°, it fills the centre section (columns at
 * -9.8°..9.8°) when straight ahead and the left section (-29.5°..-10.8°) when 20° to the left.
 */
class CameraTest {
    static final Rgb RED = new Rgb(255, 32, 32);

    /** The thesis' test: red at least twice green and twice blue. */
    static boolean isRed(Rgb c) {
        return c.red() > 2 * c.green() && c.red() > 2 * c.blue();
    }

    private static Camera cameraSeeingCylinderAt(double bearing) {
        double lens = 0.0285, d = 0.06;
        double x = lens + d * Math.cos(Math.toRadians(bearing)), z = d * Math.sin(Math.toRadians(bearing));
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"cylinders\": [{\"id\": \"red1\", \"x\": " + x + ", \"z\": " + z + "}]");
        Camera cam = w.robot("k").getCamera("camera");
        cam.enable(40);
        w.step();
        return cam;
    }

    @Test
    void aCylinderStraightAheadFillsTheCentreSection() {
        Camera cam = cameraSeeingCylinderAt(0);
        assertEquals(RED, cam.getSectionLevels(Section.CENTRE));
        assertFalse(isRed(cam.getSectionLevels(Section.LEFT)));
        assertFalse(isRed(cam.getSectionLevels(Section.RIGHT)));
    }

    @Test
    void aCylinderOnTheLeftFillsTheLeftSection() {
        Camera cam = cameraSeeingCylinderAt(-20);
        assertEquals(RED, cam.getSectionLevels(Section.LEFT));
        assertFalse(isRed(cam.getSectionLevels(Section.CENTRE)));
        assertFalse(isRed(cam.getSectionLevels(Section.RIGHT)));
    }

    @Test
    void aCylinderOnTheRightFillsTheRightSection() {
        Camera cam = cameraSeeingCylinderAt(20);
        assertEquals(RED, cam.getSectionLevels(Section.RIGHT));
        assertFalse(isRed(cam.getSectionLevels(Section.LEFT)));
        assertFalse(isRed(cam.getSectionLevels(Section.CENTRE)));
    }

    /** The thirds' levels are kept per frame: each new frame's are its own image's means, summed afresh. */
    @Test
    void sectionLevelsFollowEachFrameAsTheImagesMeans() {
        SimWorld world = TestWorlds.khepera(0, 0, 0, "\"cylinders\": [{\"id\": \"red1\", \"x\": 0.09, \"z\": 0.01}]");
        Camera cam = world.robot("k").getCamera("camera");
        cam.enable(40);
        world.step();
        world.robot("k").setSpeeds(-3, 3); // turning on the spot: the cylinder crosses the thirds
        int changed = 0;
        int[] last = null;
        for (int frame = 0; frame < 30; frame++) {
            int[] image = cam.getImage();
            int[] levels = new int[10];
            cam.copySectionLevelsInto(levels, 1);
            for (Section s : Section.values()) {
                long[] sum = new long[3];
                int from = s.firstColumn(cam.getWidth()), to = s.endColumn(cam.getWidth());
                for (int y = 0; y < cam.getHeight(); y++) {
                    for (int x = from; x < to; x++) {
                        sum[0] += Camera.imageGetRed(image, cam.getWidth(), x, y);
                        sum[1] += Camera.imageGetGreen(image, cam.getWidth(), x, y);
                        sum[2] += Camera.imageGetBlue(image, cam.getWidth(), x, y);
                    }
                }
                double n = (double) (to - from) * cam.getHeight();
                Rgb mean = new Rgb((int) Math.round(sum[0] / n), (int) Math.round(sum[1] / n), (int) Math.round(sum[2] / n));
                assertEquals(mean, cam.getSectionLevels(s), "frame " + frame + " " + s);
                int i = 1 + 3 * s.ordinal();
                assertEquals(mean, new Rgb(levels[i], levels[i + 1], levels[i + 2]), "frame " + frame + " " + s);
            }
            if (last != null && !Arrays.equals(last, levels)) {
                changed++;
            }
            last = levels;
            world.step();
        }
        assertTrue(changed > 3, "the levels changed at " + changed + " frames");
    }

    @Test
    void withoutACylinderNoSectionIsRed() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"boxes\": [{\"x\": 0.12, \"z\": 0, \"size\": 0.06}]");
        Camera cam = w.robot("k").getCamera("camera");
        cam.enable(40);
        w.step();
        for (Section s : Section.values()) {
            assertFalse(isRed(cam.getSectionLevels(s)), s.name());
        }
        // the cream box fills the centre: rows see its side between the floor and 6 cm
        assertEquals(new Rgb(255, 240, 200), cam.getSectionLevels(Section.CENTRE));
    }

    @Test
    void theFarWallsTopAndTheFloorFillTheRowsAboveAndBelow() {
        SimWorld w = TestWorlds.khepera(-0.45, 0, 0, "");
        Camera cam = w.robot("k").getCamera("camera");
        cam.enable(40);
        w.step();
        int[] img = cam.getImage();
        // the north wall is 0.92 m from the lens: the bottom row (elevation -3.28°) meets the floor
        // at 0.025 / tan(3.28°) = 0.44 m, the top row (+3.28°) meets the 10 cm wall at 7.8 cm
        assertEquals(140, Camera.imageGetRed(img, 64, 32, 7));
        assertEquals(255, Camera.imageGetGreen(img, 64, 32, 0));
    }

    @Test
    void anImageCopiedIntoAnArrayIsTheImageGiven() {
        Camera cam = cameraSeeingCylinderAt(10);
        int[] framed = new int[cam.getWidth() * cam.getHeight() + 3];
        framed[0] = -1;
        framed[framed.length - 1] = -2;
        assertTrue(cam.copyImageInto(framed, 2));
        assertArrayEquals(cam.getImage(), Arrays.copyOfRange(framed, 2, framed.length - 1));
        assertEquals(-1, framed[0]);
        assertEquals(-2, framed[framed.length - 1]);
        Camera blind = TestWorlds.khepera(0, 0, 0, "").robot("k").getCamera("camera");
        assertFalse(blind.copyImageInto(new int[blind.getWidth() * blind.getHeight()], 0));
    }

    @Test
    void theImageComesAfterOnePeriodAndSectionsNeedIt() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        Camera cam = w.robot("k").getCamera("camera");
        cam.enable(64);
        w.step(56);
        assertNull(cam.getImage());
        assertThrows(IllegalStateException.class, () -> cam.getSectionLevels(Section.CENTRE));
        w.step(8);
        assertEquals(64 * 8, cam.getImage().length);
        assertTrue(cam.hasValue());
    }

    @Test
    void sectionsSplitTheColumnsInThirds() {
        assertEquals(0, Section.LEFT.firstColumn(64));
        assertEquals(21, Section.CENTRE.firstColumn(64));
        assertEquals(42, Section.RIGHT.firstColumn(64));
        assertEquals(64, Section.RIGHT.endColumn(64));
    }
}
