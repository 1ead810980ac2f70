package jacabot.sim.robot;

import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.device.GraspHost;
import jacabot.sim.device.RayCaster;
import java.util.List;
import java.util.Random;

/** What a robot needs from the world that hosts it. Implemented by the world's engine. */
public interface RobotHost {
    /** {@return the simulated time in ms} */
    long nowMs();

    /** {@return the robot body's pose now} */
    Pose pose();

    /** {@return a ray caster ignoring this robot and what it carries} */
    RayCaster rayCaster();

    /** {@return the gripper's link to the world} */
    GraspHost graspHost();

    /** {@return a noise generator for one device, seeded from the world's seed; null when noise is off} */
    Random noise(String deviceName);

    /** {@return the floor colour (for cameras)} */
    Rgb floorColor();

    /** {@return the robot's poses, one per control step from the start, thinned past a bound (see Robot#trajectory)} */
    List<Pose> trajectory();

    /** {@return the simulated seconds spent touching walls, obstacles or other robots} */
    double contactTime();

    /** {@return the simulated seconds spent touching another robot (a team's ground truth)} */
    default double robotContactTime() {
        return 0;
    }
}
