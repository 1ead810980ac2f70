package jacabot.sim.engine;

/** The kinds of things in a world. */
public enum ObjectKind {
    WALL, BOX, CYLINDER, ROBOT
}
