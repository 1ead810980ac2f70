package jacabot.app.replay;

import jacabot.robot.link.SensorKind;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Base64;
import java.util.List;

/**
 * The camera image's reading in a step log. Format 2 writes it as {@code CAMERA_IMAGE WxH
 * rgb:BASE64}, the pixels' three bytes (red, green, blue) one after the other in base64, and as
 * {@code CAMERA_IMAGE same} when it is the image of the step before in the same gzip member (a
 * key step always holds the whole image, so a member reads on its own). Format 1 wrote the ints
 * as decimal text, {@code CAMERA_IMAGE [W, H, pixel, ...]}: four fifths of a run's log, written
 * and compressed at every step. {@link #pixels} reads both; {@link Resolver} gives back the image
 * a {@code same} stands for.
 */
public final class ImageText {
    static final String KIND = SensorKind.CAMERA_IMAGE.name();
    static final String SAME = KIND + " same";
    private static final String RGB = "rgb:";

    private ImageText() {
    }

    /**
     * {@return the image as format 2 writes it, or null when it is not {@code {W, H, W*H pixels}}
     * of 24-bit colours (then the decimal text is written)}
     */
    static String encode(int[] v) {
        if (v.length < 2 || v[0] < 0 || v[1] < 0 || (long) v[0] * v[1] != v.length - 2) {
            return null;
        }
        byte[] rgb = new byte[3 * (v.length - 2)];
        for (int i = 2, j = 0; i < v.length; i++) {
            int p = v[i];
            if ((p & 0xff000000) != 0) {
                return null;
            }
            rgb[j++] = (byte) (p >>> 16);
            rgb[j++] = (byte) (p >>> 8);
            rgb[j++] = (byte) p;
        }
        return KIND + ' ' + v[0] + 'x' + v[1] + ' ' + RGB + Base64.getEncoder().encodeToString(rgb);
    }

    /**
     * {@return a camera image reading of either format as the link carried it: {@code {W, H,
     * 0xRRGGBB...}}}
     *
     * @throws IllegalArgumentException a {@code same} (resolve it first: {@link Resolver}), another
     *     reading, or text that is not an image
     */
    public static int[] pixels(String reading) {
        if (!reading.startsWith(KIND + ' ')) {
            throw new IllegalArgumentException("not a camera image reading: " + abbreviated(reading));
        }
        String value = reading.substring(KIND.length() + 1);
        try {
            if (value.startsWith("[") && value.endsWith("]")) { // format 1
                return Arrays.stream(value.substring(1, value.length() - 1).split(", ")).mapToInt(Integer::parseInt)
                        .toArray();
            }
            int space = value.indexOf(' ');
            int x = value.indexOf('x');
            if (space > 0 && x > 0 && x < space && value.startsWith(RGB, space + 1)) {
                int w = Integer.parseInt(value.substring(0, x));
                int h = Integer.parseInt(value.substring(x + 1, space));
                byte[] rgb = Base64.getDecoder().decode(value.substring(space + 1 + RGB.length()));
                if (rgb.length != 3L * w * h) {
                    throw new IllegalArgumentException(rgb.length + " bytes of pixels for " + w + "x" + h);
                }
                int[] out = new int[2 + w * h];
                out[0] = w;
                out[1] = h;
                for (int i = 2, j = 0; i < out.length; i++, j += 3) {
                    out[i] = (rgb[j] & 0xff) << 16 | (rgb[j + 1] & 0xff) << 8 | rgb[j + 2] & 0xff;
                }
                return out;
            }
        } catch (IllegalArgumentException e) { // NumberFormatException too
            throw new IllegalArgumentException("not a camera image: " + abbreviated(reading) + " (" + e.getMessage() + ")");
        }
        throw new IllegalArgumentException("not a camera image: " + abbreviated(reading));
    }

    private static String abbreviated(String s) {
        return s.length() > 60 ? s.substring(0, 60) + "..." : s;
    }

    /**
     * Reads a gzip member's steps in order and gives each {@code same} back as the image it stands
     * for. One per sequence of steps that starts at a key step.
     */
    static final class Resolver {
        private String last;

        /** {@return {@code readings} with a {@code same} replaced by the last image; the same list when there is none} */
        List<String> resolve(List<String> readings) {
            List<String> out = readings;
            for (int i = 0; i < readings.size(); i++) {
                String r = readings.get(i);
                if (r.equals(SAME)) {
                    if (last == null) {
                        throw new IllegalArgumentException("'" + SAME + "' with no image before it in its gzip member");
                    }
                    if (out == readings) {
                        out = new ArrayList<>(readings);
                    }
                    out.set(i, last);
                } else if (r.startsWith(KIND + ' ')) {
                    last = r;
                }
            }
            return out;
        }
    }
}
