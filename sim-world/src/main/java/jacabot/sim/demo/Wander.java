package jacabot.sim.demo;

import jacabot.sim.SimWorld;
import jacabot.sim.device.Camera;
import jacabot.sim.device.DistanceSensor;
import jacabot.sim.robot.Robot;
import java.util.List;
import java.util.function.Consumer;

/**
 * A fixed driving pattern for demos, renders and the benchmark (not a thesis controller): every
 * device enabled at the control step; forward with a slow left/right weave, turning on the spot
 * while a front sensor reads over 350 (the thesis' obstacle threshold). Deterministic.
 */
public final class Wander implements Consumer<SimWorld> {
    private boolean enabled;
    private long step;

    @Override
    public void accept(SimWorld world) {
        if (!enabled) {
            enableAll(world);
            enabled = true;
        }
        for (Robot r : world.robots()) {
            drive(r);
        }
        step++;
    }

    private static void enableAll(SimWorld world) {
        int period = world.controlStep();
        for (Robot r : world.robots()) {
            for (DistanceSensor d : r.distanceSensors()) {
                d.enable(period);
            }
            if (r.model().camera() != null) {
                Camera c = r.getCamera(r.model().camera().name());
                c.enable(period);
            }
            if (r.model().gps()) {
                r.getGps("gps").enable(period);
            }
            if (r.model().compass()) {
                r.getCompass("compass").enable(period);
            }
            if (r.hasBattery()) {
                r.getBattery().enable(period);
            }
            if (r.hasGripper()) {
                r.getGripper().enableForceFeedback(period);
                r.getGripper().enablePresence(period);
            }
        }
    }

    private void drive(Robot r) {
        List<DistanceSensor> ds = r.distanceSensors();
        double left = 0, right = 0;
        for (DistanceSensor d : ds) {
            double v = d.getValue();
            if (Double.isNaN(v) || d.name().equals("left") && ds.size() > 2 || d.name().equals("right") && ds.size() > 2) {
                continue;
            }
            if (d.name().contains("left")) {
                left = Math.max(left, v);
            } else if (d.name().contains("right")) {
                right = Math.max(right, v);
            } else {
                left = Math.max(left, v);
                right = Math.max(right, v);
            }
        }
        double max = r.getWheels().getMaxSpeed();
        if (left > 350 || right > 350) {
            double turn = left >= right ? 1 : -1;
            r.setSpeeds(turn * max / 2, -turn * max / 2);
        } else {
            long phase = step / 100 % 4;
            double weave = phase == 1 ? 0.6 : phase == 3 ? -0.6 : 0;
            r.setSpeeds(max * (weave >= 0 ? 1 : 1 + weave), max * (weave <= 0 ? 1 : 1 - weave));
        }
    }
}
