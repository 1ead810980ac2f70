package jacabot.app.world;

import static jacabot.app.world.Floor.num;
import static jacabot.app.world.Floor.round2;

import jacabot.robot.Experiment;
import jacabot.sim.robot.RobotModel;
import jacabot.sim.world.Footprint;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The scripted faults of a generated world (the world file's {@code events}): an obstacle moved, a
 * cylinder that jumps away as the robot takes hold of it, a carried cylinder knocked out, the battery
 * drained; 0 to 3 of those that make sense for the experiment, at random times.
 */
final class ScriptedFaults {
    private ScriptedFaults() {
    }

    /**
     * {@return the faults' events as world-file JSON objects}
     * @param boxes the obstacles drawn, each (x, z, sx, sz, heading), named box1, box2, ... in this order
     * @param cylinders the cylinders' ids
     */
    static List<String> draw(Experiment experiment, RobotModel model, Floor floor, SplittableRandom random,
                             List<double[]> boxes, List<String> cylinders) {
        List<String> kinds = new ArrayList<>();
        if (!boxes.isEmpty()) {
            kinds.add("move-box");
        }
        if (!cylinders.isEmpty()) {
            kinds.add("move-cylinder-in-grip");
            kinds.add("knock");
        }
        if (experiment.needsCharger()) {
            kinds.add("drain");
        }
        List<String> events = new ArrayList<>();
        int n = kinds.isEmpty() ? 0 : random.nextInt(4);
        for (int i = 0; i < n; i++) {
            String kind = kinds.get(random.nextInt(kinds.size()));
            double at = Math.round(random.nextDouble(20, 480));
            String robot = experiment.robot();
            switch (kind) {
                case "move-box" -> {
                    int b = random.nextInt(boxes.size());
                    double[] to = floor.spotForBox(boxes.get(b));
                    if (to != null) {
                        events.add("{ \"at\": " + num(at) + ", \"do\": \"move\", \"object\": \"box" + (b + 1) + "\", \"x\": "
                                + num(to[0]) + ", \"z\": " + num(to[1]) + " }");
                    }
                }
                case "move-cylinder-in-grip" -> {
                    // when the robot is about to take hold of it (centres within reach), the cylinder jumps away
                    String c = cylinders.get(random.nextInt(cylinders.size()));
                    double[] to = floor.spot(0.0125, floor.gap(), 0.0);
                    if (to != null) {
                        floor.place(Footprint.circle(to[0], to[1], 0.0125));
                        events.add("{ \"when\": { \"robot\": \"" + robot + "\", \"near\": \"" + c + "\", \"within\": "
                                + num(model.radius() + 0.03) + " }, \"after\": " + num(round2(floor.uniform(0.2, 2.0)))
                                + ", \"do\": \"move\", \"object\": \"" + c + "\", \"x\": " + num(to[0]) + ", \"z\": " + num(to[1]) + " }");
                    }
                }
                case "knock" -> {
                    // some seconds after the robot reached a cylinder: knocked out if it carries it then
                    String c = cylinders.get(random.nextInt(cylinders.size()));
                    events.add("{ \"when\": { \"robot\": \"" + robot + "\", \"near\": \"" + c + "\", \"within\": "
                            + num(model.radius() + 0.03) + " }, \"after\": " + num(Math.round(random.nextDouble(4, 20)))
                            + ", \"do\": \"knock\", \"robot\": \"" + robot + "\" }");
                }
                default -> events.add("{ \"at\": " + num(at) + ", \"do\": \"drain\", \"robot\": \"" + robot + "\", \"amount\": "
                        + num(Math.round(random.nextDouble(100, 300))) + " }");
            }
        }
        return events;
    }
}
