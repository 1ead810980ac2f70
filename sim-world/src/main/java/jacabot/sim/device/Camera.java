package jacabot.sim.device;

import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import java.util.List;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * A colour camera, after Webots' {@code Camera}: a {@code width × height} image rendered by ray
 * casting. Column c looks at relative bearing {@code -fov/2 + (c + 0.5) fov / width} (column 0 is
 * the robot's left); row r at elevation {@code vfov/2 - (r + 0.5) vfov / height} with
 * {@code vfov = fov × height / width} (square pixels; row 0 is the top). A pixel takes the colour of
 * the first object whose side the ray meets between the floor and the object's height; if the
 * ray reaches the floor first it sees the floor colour, and past everything the background.
 * Objects are flat-shaded (no lighting), so a red cylinder gives exactly its colour.
 */
public final class Camera extends Sensor {
    private final int width, height;
    private final double fov, mountHeight, range;
    private final Supplier<Pose> mount;
    private final RayCaster caster;
    private final Rgb floor, background;
    private int[] image;
    /** The last image's thirds' mean levels ({@link #sectionLevels}), and whether they are the last image's. */
    private final int[] levels = new int[9];
    private boolean levelsFresh;
    /** Each row's ray slope (rise per metre), the same for every column and frame. */
    private final double[] rowSlopes;

    /**
     * @param fov         horizontal field of view in degrees
     * @param mountHeight the lens' height above the floor in metres
     * @param range       the farthest distance seen, metres
     */
    public Camera(String name, LongSupplier clock, int width, int height, double fov, double mountHeight, double range,
                  Supplier<Pose> mount, RayCaster caster, Rgb floor, Rgb background) {
        super(name, clock);
        if (width < 3 || height < 1) {
            throw new IllegalArgumentException("a camera needs width >= 3 and height >= 1");
        }
        this.width = width;
        this.height = height;
        this.fov = fov;
        this.mountHeight = mountHeight;
        this.range = range;
        this.mount = mount;
        this.caster = caster;
        this.floor = floor;
        this.background = background;
        double vfov = fov * height / width;
        this.rowSlopes = new double[height];
        for (int r = 0; r < height; r++) {
            rowSlopes[r] = Math.tan(Math.toRadians(vfov / 2 - (r + 0.5) * vfov / height));
        }
    }

    public int getWidth() {
        return width;
    }

    public int getHeight() {
        return height;
    }

    /** {@return the horizontal field of view in degrees} */
    public double getFov() {
        return fov;
    }

    /** {@return the last image, row-major, each pixel packed 0xRRGGBB; null before the first period} */
    public int[] getImage() {
        return hasValue() ? image.clone() : null;
    }

    /**
     * Copies the last image into {@code dst} from {@code offset} on (as {@link #getImage()} gives it,
     * without an array of its own). {@return whether there was an image}
     */
    public boolean copyImageInto(int[] dst, int offset) {
        if (!hasValue()) {
            return false;
        }
        System.arraycopy(image, 0, dst, offset, image.length);
        return true;
    }

    /** {@return the red level 0..255 of pixel (x, y) of an image from {@link #getImage()}} */
    public static int imageGetRed(int[] image, int width, int x, int y) {
        return (image[y * width + x] >> 16) & 0xFF;
    }

    /** {@return the green level 0..255 of a pixel} */
    public static int imageGetGreen(int[] image, int width, int x, int y) {
        return (image[y * width + x] >> 8) & 0xFF;
    }

    /** {@return the blue level 0..255 of a pixel} */
    public static int imageGetBlue(int[] image, int width, int x, int y) {
        return image[y * width + x] & 0xFF;
    }

    /**
     * {@return the mean red, green and blue levels (rounded) of one third of the last image}
     *
     * @throws IllegalStateException before the first image
     */
    public Rgb getSectionLevels(Section section) {
        int[] l = sectionLevels();
        int i = 3 * section.ordinal();
        return new Rgb(l[i], l[i + 1], l[i + 2]);
    }

    /**
     * Copies the three thirds' mean levels of the last image (left, centre, right; red, green, blue
     * each, as {@link #getSectionLevels} gives them) into {@code dst} from {@code offset} on.
     *
     * @throws IllegalStateException before the first image
     */
    public void copySectionLevelsInto(int[] dst, int offset) {
        System.arraycopy(sectionLevels(), 0, dst, offset, 9);
    }

    /**
     * The thirds' levels of the last image, summed in one pass over it the first time they are asked
     * for after a frame (a controller asks every step, the baseline's image tests several times).
     */
    private int[] sectionLevels() {
        if (!hasValue()) {
            throw new IllegalStateException("camera '" + name() + "' has no image yet: enable it and step one period");
        }
        if (levelsFresh) {
            return levels;
        }
        long[] sums = new long[9];
        int[] ends = {Section.LEFT.endColumn(width), Section.CENTRE.endColumn(width), Section.RIGHT.endColumn(width)};
        for (int y = 0; y < height; y++) {
            int row = y * width;
            int x = 0;
            for (int s = 0; s < 3; s++) {
                long r = 0, g = 0, b = 0;
                for (int end = ends[s]; x < end; x++) {
                    int p = image[row + x];
                    r += (p >> 16) & 0xFF;
                    g += (p >> 8) & 0xFF;
                    b += p & 0xFF;
                }
                sums[3 * s] += r;
                sums[3 * s + 1] += g;
                sums[3 * s + 2] += b;
            }
        }
        for (int s = 0; s < 3; s++) {
            Section section = Section.values()[s];
            long n = (long) (section.endColumn(width) - section.firstColumn(width)) * height;
            for (int c = 0; c < 3; c++) {
                levels[3 * s + c] = (int) Math.round((double) sums[3 * s + c] / n);
            }
        }
        levelsFresh = true;
        return levels;
    }

    @Override
    protected void sample() {
        if (image == null) {
            image = new int[width * height];
        }
        renderInto(image); // the last image's own array: getImage() and copyImageInto() copy it
        levelsFresh = false;
    }

    /** {@return an image of what the camera sees now} */
    public int[] render() {
        int[] img = new int[width * height];
        renderInto(img);
        return img;
    }

    private void renderInto(int[] img) {
        Pose p = mount.get();
        double[] bearings = new double[width];
        for (int c = 0; c < width; c++) {
            bearings[c] = p.heading() - fov / 2 + (c + 0.5) * fov / width;
        }
        // one broad phase for all columns; a column reads nothing behind a hit that fills its top row
        List<List<RayHit>> fan = caster.castFan(p.position(), bearings, range, this::fillsTopRow);
        for (int c = 0; c < width; c++) {
            renderColumn(img, c, fan.get(c));
        }
    }

    /**
     * Whether a pixel's ray stops at a hit: it passes below the floor before it, or meets the
     * object's side. A row's height along the ray, {@code mountHeight + distance × slope}, falls with
     * the row (the slopes fall, the distance is not negative), so a hit that stops some row stops
     * every row below it too.
     */
    private static boolean stops(double y, RayHit hit) {
        return y < 0 || y <= hit.height();
    }

    /** Whether a hit stops the top row's ray, and so every row's (see {@link #stops}): nothing behind it is seen. */
    private boolean fillsTopRow(RayHit hit) {
        return stops(mountHeight + hit.distance() * rowSlopes[0], hit);
    }

    /**
     * Fills column c: each row takes the first hit, nearest first, that stops its ray (the floor if
     * the ray reached the floor first, else the object's colour); a row no hit stops sees the floor
     * if the ray reaches it within range, else the background. The hits that stop rows stop a
     * suffix of the rows still open (see {@link #stops}), so the column is filled from the bottom
     * up, each pixel once, and ends at the first hit that stops the top row.
     */
    private void renderColumn(int[] img, int c, List<RayHit> hits) {
        int open = height; // the rows 0 .. open - 1 are not filled yet
        for (int i = 0, n = hits.size(); i < n && open > 0; i++) {
            RayHit hit = hits.get(i);
            while (open > 0) {
                double y = mountHeight + hit.distance() * rowSlopes[open - 1];
                if (!stops(y, hit)) {
                    break; // nor does it stop any row above
                }
                img[(open - 1) * width + c] = y < 0 ? floor.packed() : hit.color().packed();
                open--;
            }
        }
        for (int r = 0; r < open; r++) {
            double slope = rowSlopes[r];
            img[r * width + c] = slope < 0 && mountHeight + range * slope < 0 ? floor.packed() : background.packed();
        }
    }
}
