package jacabot.sim.device;

/** The thirds of a camera image the thesis' image processing looks at. */
public enum Section {
    LEFT, CENTRE, RIGHT;

    /** {@return the first column of this section in an image {@code width} pixels wide} */
    public int firstColumn(int width) {
        return ordinal() * width / 3;
    }

    /** {@return one past the last column of this section} */
    public int endColumn(int width) {
        return (ordinal() + 1) * width / 3;
    }
}
