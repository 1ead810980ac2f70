package jacabot.robot.baseline;

import jacabot.sim.SimWorld;
import java.util.function.Consumer;

public class SuspendResumeBaseline extends NavigationBaseline {
    public SuspendResumeBaseline(SimWorld world, String robotName, long seed, Consumer<String> console) {
        super(world, robotName, seed, console);
    }
}
