package jacabot.sim.device;

/** A device of a robot, looked up by name as in Webots ({@code robot.getDevice(name)}). */
public interface Device {
    /** {@return the device's name, unique on its robot} */
    String name();

    /** {@return the device's name (Webots' spelling)} */
    default String getName() {
        return name();
    }
}
