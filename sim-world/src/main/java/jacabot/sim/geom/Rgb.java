package jacabot.sim.geom;

import java.util.Locale;

/** An 8-bit RGB colour, as Webots cameras return it. Components are 0..255. */
public record Rgb(int red, int green, int blue) {
    public static final Rgb WHITE = new Rgb(255, 255, 255);
    public static final Rgb RED = new Rgb(255, 32, 32);

    /** Checks the components. */
    public Rgb {
        if (red < 0 || red > 255 || green < 0 || green > 255 || blue < 0 || blue > 255) {
            throw new IllegalArgumentException("colour components must be in 0..255");
        }
    }

    /** {@return the colour packed as 0xRRGGBB} */
    public int packed() {
        return (red << 16) | (green << 8) | blue;
    }

    /** {@return the colour as "#RRGGBB"} */
    public String hex() {
        return String.format(Locale.ROOT, "#%02X%02X%02X", red, green, blue);
    }

    /**
     * Parses "#RRGGBB" or one of the names red, green, blue, white, grey, black, yellow, cream.
     *
     * @throws IllegalArgumentException when the text is neither
     */
    public static Rgb parse(String text) {
        String t = text.trim().toLowerCase(Locale.ROOT);
        switch (t) {
            case "red": return RED;
            case "green": return new Rgb(32, 200, 32);
            case "blue": return new Rgb(32, 32, 230);
            case "white": return WHITE;
            case "grey": case "gray": return new Rgb(128, 128, 128);
            case "black": return new Rgb(0, 0, 0);
            case "yellow": return new Rgb(240, 220, 40);
            case "cream": return new Rgb(255, 240, 200);
            default: break;
        }
        if (t.matches("#[0-9a-f]{6}")) {
            int v = Integer.parseInt(t.substring(1), 16);
            return new Rgb((v >> 16) & 0xFF, (v >> 8) & 0xFF, v & 0xFF);
        }
        throw new IllegalArgumentException("not a colour: '" + text + "' (use #RRGGBB or red, green, blue, white, grey, black, yellow, cream)");
    }
}
