package jacabot.robot.link;

import java.util.Optional;

/**
 * The registry of {@link SensorInfo} ids: which reading an id stands for and which of the four
 * shapes of Appendix A carries it. The thesis' middleware switches on such constants
 * ({@code case RIGHT_DISTANCE_SENSOR:}, {@code case BATTERY:}); here they are defined once, for
 * both sides of the link. Ids are part of the protocol: never renumber, only add.
 */
public enum SensorKind {
    LEFT_DISTANCE(1, Shape.SCALAR, "distance sensor \"left\""),
    RIGHT_DISTANCE(2, Shape.SCALAR, "distance sensor \"right\""),
    CENTRAL_DISTANCE(3, Shape.SCALAR, "distance sensor \"front\""),
    FRONT_LEFT_DISTANCE(4, Shape.SCALAR, "distance sensor \"front-left\""),
    FRONT_RIGHT_DISTANCE(5, Shape.SCALAR, "distance sensor \"front-right\""),
    /** Mean RGB of the camera's left, centre and right thirds: {r,g,b, r,g,b, r,g,b}. */
    CAMERA_SECTIONS(10, Shape.INTS, "camera image sections (left, centre, right RGB)"),
    /** The whole camera image: {width, height, pixel 0xRRGGBB...} row-major (off by default). */
    CAMERA_IMAGE(11, Shape.INTS, "camera image (width, height, pixels)"),
    /** GPS position {x, y, z} in metres. */
    GPS(20, Shape.COORD, "GPS position"),
    /** Compass north vector {x, y, z} as Webots gives it. */
    COMPASS(21, Shape.COORD, "compass north vector"),
    /** Battery energy in joules. */
    BATTERY(30, Shape.SCALAR, "battery energy"),
    /** Gripper force feedback in newtons (negative while holding). */
    GRIP_FORCE(40, Shape.SCALAR, "gripper force feedback"),
    /** 1 when an object is between the fingers, else 0. */
    GRIP_PRESENCE(41, Shape.SCALAR, "gripper presence"),
    /** {arm position 0 up..1 down, grip position 0 open..1 closed}. */
    GRIPPER_POSITIONS(42, Shape.DOUBLES, "arm and finger positions"),
    /** The wheel speeds in effect {left, right}: what the actuators were last given. */
    WHEEL_SPEEDS(50, Shape.DOUBLES, "wheel speeds");

    /** Which of the four {@link SensorInfo} constructors carries the value. */
    public enum Shape { SCALAR, COORD, INTS, DOUBLES }

    private final int id;
    private final Shape shape;
    private final String description;
    private final Optional<SensorKind> asOptional = Optional.of(this);

    SensorKind(int id, Shape shape, String description) {
        this.id = id;
        this.shape = shape;
        this.description = description;
    }

    /** {@return the id carried by {@link SensorInfo#getId()}} */
    public int id() {
        return id;
    }

    public Shape shape() {
        return shape;
    }

    public String description() {
        return description;
    }

    /** {@return the kind of an id, empty for ids this version does not know} */
    public static Optional<SensorKind> of(int id) {
        for (SensorKind k : ALL) {
            if (k.id == id) {
                return k.asOptional;
            }
        }
        return Optional.empty();
    }

    /** The kinds, made once: {@link #of} runs for every reading, and {@code values()} copies its array. */
    private static final SensorKind[] ALL = values();

    /** {@return the kind of a distance sensor named as on our robot models, empty for other names} */
    public static Optional<SensorKind> ofDistanceSensor(String deviceName) {
        switch (deviceName) {
            case "left": return Optional.of(LEFT_DISTANCE);
            case "right": return Optional.of(RIGHT_DISTANCE);
            case "front": return Optional.of(CENTRAL_DISTANCE);
            case "front-left": return Optional.of(FRONT_LEFT_DISTANCE);
            case "front-right": return Optional.of(FRONT_RIGHT_DISTANCE);
            default: return Optional.empty();
        }
    }
}
