package jacabot.experiments;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * A red cylinder seen far off in the whole camera image (not in the thesis): the widest run of columns
 * holding a red pixel, by the thesis' red test ({@code r > 40}, red at least twice green and blue).
 * The three section means of Chapter 4 §2.2 see a cylinder only within about 15 cm, where it
 * fills a third of the image; one column of a 64-column image is under a degree, so a 2.5 cm
 * cylinder shows from about a metre and a half.
 *
 * @param offset  degrees from the image's centre to the run's centre, positive to the right
 * @param columns the run's width in columns
 * @param distance a rough distance in metres from the apparent width (the cylinder's radius known)
 */
public record CylinderSighting(double offset, int columns, double distance) {
    /** The experiments' cylinders: radius in metres. */
    static final double CYLINDER_RADIUS = 0.0125;

    /**
     * {@return the widest red run of an image framed as {width, height, pixels...}, or empty}: the
     * first of {@link #all}
     *
     * @param fov the camera's horizontal field of view, degrees
     */
    public static Optional<CylinderSighting> find(int[] framed, double fov) {
        List<CylinderSighting> runs = all(framed, fov); // no stream: most images have none
        return runs.isEmpty() ? Optional.empty() : Optional.of(runs.get(0));
    }

    /**
     * {@return every red run of an image framed as {width, height, pixels...}, the widest first (of
     * runs as wide, the leftmost)}: the storage area's pile is the widest in view near it, and a
     * lone cylinder beside it is another run
     *
     * @param fov the camera's horizontal field of view, degrees
     */
    public static List<CylinderSighting> all(int[] framed, double fov) {
        List<CylinderSighting> runs = new ArrayList<>();
        if (framed.length < 2) {
            return runs;
        }
        int width = framed[0], height = framed[1];
        if (width <= 0 || height <= 0 || framed.length != 2 + (long) width * height) {
            return runs;
        }
        boolean[] redColumns = redColumns(framed, width, height);
        if (redColumns == null) {
            return runs;
        }
        double perColumn = fov / width;
        int runFrom = -1;
        for (int c = 0; c <= width; c++) {
            boolean red = c < width && redColumns[c];
            if (red && runFrom < 0) {
                runFrom = c;
            } else if (!red && runFrom >= 0) {
                int length = c - runFrom;
                double offset = (runFrom + length / 2.0 - width / 2.0) * perColumn;
                double distance = CYLINDER_RADIUS / Math.tan(Math.toRadians(length * perColumn / 2));
                runs.add(new CylinderSighting(offset, length, distance));
                runFrom = -1;
            }
        }
        runs.sort(Comparator.comparingInt(CylinderSighting::columns).reversed()); // stable: the leftmost first
        return runs;
    }

    /**
     * Per red level, the green and blue levels a pixel of it is red below ({@link
     * ObjectPickingMiddleware#isRed}: bright enough, and red above the ratio times green and times blue,
     * each condition on green and blue alone and true below a bound): one look-up for every pixel of
     * every image where the test multiplied two doubles (4 % of the agent's thread in experiment 4).
     * {@code CylinderSightingTest} checks it against the test on every colour.
     */
    static final int[] GREEN_BLUE_BELOW = new int[256];

    static {
        for (int r = 0; r < 256; r++) {
            int g = 0;
            while (g < 256 && ObjectPickingMiddleware.isRed(r, g, 0)) {
                g++;
            }
            GREEN_BLUE_BELOW[r] = g;
        }
    }

    /**
     * {@return whether each column holds a red pixel, or null when none does (most images)}: the
     * image read row by row, as it lies in the array, a column's pixels passed over once it is red
     * (a column at a time strode through the array: 3 % of the agent's thread in experiment 4)
     */
    static boolean[] redColumns(int[] framed, int width, int height) {
        boolean[] red = null;
        for (int y = 0, i = 2; y < height; y++) {
            for (int c = 0; c < width; c++, i++) {
                if (red != null && red[c]) {
                    continue;
                }
                int p = framed[i], below = GREEN_BLUE_BELOW[(p >> 16) & 0xFF];
                if (((p >> 8) & 0xFF) < below && (p & 0xFF) < below) {
                    if (red == null) {
                        red = new boolean[width];
                    }
                    red[c] = true;
                }
            }
        }
        return red;
    }
}
