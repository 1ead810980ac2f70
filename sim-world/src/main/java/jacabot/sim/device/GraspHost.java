package jacabot.sim.device;

/** What a gripper needs from the world: find, attach and let go of cylinders. */
public interface GraspHost {
    /** {@return the id of a free cylinder whose centre lies between the open fingers (arm down), or null} */
    String graspable();

    /** Attaches a cylinder to the fingers: it follows the robot and no longer collides. */
    void attach(String cylinderId);

    /**
     * Lets the carried cylinder go: set down on the floor between the fingers, or, when
     * {@code knocked}, thrown beside the robot.
     */
    void release(String cylinderId, boolean knocked);
}
