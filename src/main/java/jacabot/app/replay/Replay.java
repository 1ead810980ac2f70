package jacabot.app.replay;

import com.fasterxml.jackson.core.JsonProcessingException;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.RobotView;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.geom.Pose;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A recorded run, read back from its step log into frames: the world, the robot's body and the
 * agent's mind at every control step. The recorder streams the log to disk; a replay holds the
 * frames of one run (a 10-minute run is some 15 000 frames sharing their beliefs).
 */
public final class Replay {
    /** One control step as replayed. */
    public record Frame(long timeMs, StepLog.Body body, List<String> commands, List<String> readings,
            Map<String, StepLog.Moved> objects, MindState mind, int trajectoryLength) {
    }

    private final Path dir;
    private final StepLog.Header header;
    private final List<Frame> frames;
    private final List<Pose> trajectory;

    private Replay(Path dir, StepLog.Header header, List<Frame> frames, List<Pose> trajectory) {
        this.dir = dir;
        this.header = header;
        this.frames = frames;
        this.trajectory = trajectory;
    }

    /**
     * Reads {@code dir/steps.jsonl.gz} (or a step log file given directly).
     *
     * @throws IOException with the file's name when it is missing or not a step log
     */
    public static Replay open(Path dirOrFile) throws IOException {
        Path file = Files.isDirectory(dirOrFile) ? dirOrFile.resolve(StepLog.FILE) : dirOrFile;
        if (!Files.isRegularFile(file)) {
            throw new IOException(file + ": no step log (written by every headless `jacabot experiment` run)");
        }
        var frames = new ArrayList<Frame>();
        var trajectory = new ArrayList<Pose>();
        StepLog.Header header;
        try (var in = new StepLog.Reader(file)) {
            header = in.header();
            var state = StepState.from(header);
            StepLog.Step s;
            while ((s = in.next()) != null) {
                MindState mind = state.apply(s);
                Map<String, StepLog.Moved> objs = state.objects();
                trajectory.add(new Pose(s.body().x(), s.body().z(), s.body().heading()));
                frames.add(new Frame(s.timeMs(), s.body(), s.commands(), s.readings(), objs, mind, trajectory.size()));
            }
        } catch (JsonProcessingException e) {
            throw new IOException(file + ": not a jacabot step log: " + e.getOriginalMessage());
        }
        return new Replay(dirOrFile, header, List.copyOf(frames), trajectory);
    }

    public Path dir() {
        return dir;
    }

    public StepLog.Header header() {
        return header;
    }

    public List<Frame> frames() {
        return frames;
    }

    /** {@return the index of the last frame at or before {@code timeMs}} */
    public int indexAt(long timeMs) {
        int lo = 0, hi = frames.size() - 1, best = 0;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            if (frames.get(mid).timeMs() <= timeMs) {
                best = mid;
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        return best;
    }

    /** {@return the robot's side of frame {@code i}, for the inspector} */
    public RobotView robotView(int i) {
        Frame f = frames.get(i);
        var b = f.body();
        return new RobotView(f.timeMs(), b.x(), b.z(), b.heading(), b.battery(), b.left(), b.right(), f.commands());
    }

    /** {@return the world at frame {@code i}, to paint with the viewer's renderer} */
    public WorldSnapshot world(int i) {
        Frame f = frames.get(i);
        WorldSnapshot start = header.start();
        var objects = new ArrayList<ObjectState>();
        for (ObjectState o : start.objects()) {
            StepLog.Moved m = f.objects().get(o.id());
            if (o.kind() == ObjectKind.ROBOT) {
                continue;
            }
            objects.add(m == null ? o : new ObjectState(o.id(), o.kind(), new Pose(m.x(), m.z(), m.heading()), o.sizeX(),
                    o.sizeZ(), o.height(), o.color(), o.movable(), m.carriedBy()));
        }
        var robots = new ArrayList<WorldSnapshot.RobotState>();
        for (WorldSnapshot.RobotState r : start.robots()) {
            var b = f.body();
            robots.add(new WorldSnapshot.RobotState(r.name(), r.model(), new Pose(b.x(), b.z(), b.heading()), r.radius(),
                    r.color(), trajectory.subList(0, f.trajectoryLength()), List.of(), null, 0, 0, r.armPosition(),
                    r.gripPosition(), b.held(), b.battery() == null ? Double.NaN : b.battery(), r.batteryMax(),
                    b.contactTime()));
        }
        return new WorldSnapshot(start.name(), f.timeMs(), start.arena(), start.storage(), start.charger(), objects, robots);
    }
}
