package jacabot.sim;

/** The kinds of things in a world. */
public enum ObjectKind {
    WALL, BOX, CYLINDER, ROBOT
}
