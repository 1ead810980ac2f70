package jacabot.app.run;

import jacabot.experiments.link.LinkEvent;
import jacabot.experiments.link.StepData;
import jacabot.robot.link.SensorInfo;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * The middleware end of a team robot's link: collects a step's readings until its marker, and
 * knows whether the link is up. Its events come on the link's thread (the controller's simulation
 * thread in memory, the link's reading thread over a socket); the team's run takes the steps on its
 * own, so each arrival wakes it ({@code onArrival}).
 */
final class TeamStepCollector implements Consumer<LinkEvent> {
    private final Runnable onArrival;
    private final List<SensorInfo> readings = new ArrayList<>();
    private StepData pending;
    private String robot;
    private boolean connected, ended;

    TeamStepCollector(Runnable onArrival) {
        this.onArrival = onArrival;
    }

    @Override
    public void accept(LinkEvent e) {
        synchronized (this) {
            if (e instanceof LinkEvent.Connected c) {
                readings.clear();
                robot = c.robotName();
                connected = true;
            } else if (e instanceof LinkEvent.Reading r) {
                readings.add(r.info());
                return;
            } else if (e instanceof LinkEvent.StepMarker m) {
                pending = new StepData(m.step(), m.simTimeMs(), List.copyOf(readings));
                readings.clear();
            } else if (e instanceof LinkEvent.Disconnected && connected) {
                ended = true; // the controller said goodbye, or dropped: nothing more will come
            } else {
                return;
            }
        }
        onArrival.run();
    }

    /** {@return the step whose marker came and that nobody took yet, null if none} */
    synchronized StepData take() {
        StepData d = pending;
        pending = null;
        return d;
    }

    /** {@return the simulated time of the step waiting, −1 if none} */
    synchronized long peekTime() {
        return pending == null ? -1 : pending.simTimeMs();
    }

    synchronized boolean hasStep() {
        return pending != null;
    }

    /** {@return the robot named by the controller's greeting, null before it connected} */
    synchronized String robot() {
        return robot;
    }

    synchronized boolean connectedOnce() {
        return connected;
    }

    /** {@return whether the link ended after it came up} */
    synchronized boolean ended() {
        return ended;
    }
}
