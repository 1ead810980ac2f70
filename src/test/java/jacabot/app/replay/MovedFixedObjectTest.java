package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A box the world file's events move (a fixed body, teleported) is in the step log from the step it
 * moved, and in every key step after, so a replay, from the start or from a key step, draws it where
 * it went; walls and boxes that stay put are never written. The inspector's live view places it
 * where it went too, and no fixed box that stayed put.
 */
class MovedFixedObjectTest {
    @Test
    void aBoxAnEventMovedIsReplayedWhereItWent(@TempDir Path dir) throws Exception {
        SimWorld w = SimWorld.load(SyntheticRun.ROOT.resolve("worlds/navigation.json"));
        var start = w.snapshot();
        ObjectState box = start.objects().stream().filter(o -> o.kind() == ObjectKind.BOX && !o.movable()).findFirst()
                .orElseThrow(() -> new AssertionError("the navigation world has a fixed box"));
        var header = new StepLog.Header(StepLog.FORMAT, "navigation", w.name(), 1, 40, w.robots().get(0).name(),
                "synthetic.asl", start, null);
        Pose went = new Pose(box.pose().x() + 0.2, box.pose().z() - 0.1, box.pose().heading());
        int movedAt = 30; // within the first gzip member; the key steps at 100 and 200 must carry it
        try (var log = new StepLog.Writer(dir.resolve(StepLog.FILE), header)) {
            for (int i = 0; i < 250; i++) {
                var objects = new ArrayList<ObjectState>();
                for (ObjectState o : start.objects()) {
                    objects.add(i >= movedAt && o.id().equals(box.id()) ? new ObjectState(o.id(), o.kind(), went, o.sizeX(),
                            o.sizeZ(), o.height(), o.color(), o.movable(), o.carriedBy()) : o);
                }
                var body = new StepLog.Body(0, 0, 0, null, 0, 0, null, 0);
                log.stepText(40L * (i + 1), body, List.of(), List.of(), null, objects);
            }
        }
        var writtenAt = new ArrayList<Integer>();
        var state = StepState.from(readHeader(dir));
        try (var r = new StepLog.Reader(dir.resolve(StepLog.FILE))) {
            int i = 0;
            for (StepLog.Step s = r.next(); s != null; s = r.next(), i++) {
                for (ObjectState o : start.objects()) {
                    if (o.kind() == ObjectKind.WALL || o.kind() == ObjectKind.BOX && !o.id().equals(box.id())) {
                        assertFalse(s.moved().containsKey(o.id()), o.id() + " written at step " + i + " though it stood still");
                    }
                }
                if (s.moved().containsKey(box.id())) {
                    writtenAt.add(i);
                }
                state.apply(s);
                StepLog.Moved m = state.objects().get(box.id());
                if (i >= movedAt) {
                    assertNotNull(m, "the moved box at step " + i);
                    assertEquals(went.x(), m.x(), 1e-9);
                    assertEquals(went.z(), m.z(), 1e-9);
                }
            }
            assertEquals(250, i);
        }
        assertEquals(List.of(movedAt, 100, 200), writtenAt, "written when it moved and in each key step after");
    }

    @Test
    void theLiveViewShowsABoxAnEventMovedWhereItWent() throws Exception {
        String json = Files.readString(SyntheticRun.ROOT.resolve("worlds/navigation.json"));
        SimWorld plain = SimWorld.parse(json, "navigation.json");
        ObjectState box = plain.snapshot().objects().stream().filter(o -> o.kind() == ObjectKind.BOX && !o.movable())
                .findFirst().orElseThrow(() -> new AssertionError("the navigation world has a fixed box"));
        double x = box.pose().x() + 0.2, z = box.pose().z() - 0.1;
        var tree = (ObjectNode) StepLog.JSON.readTree(json);
        tree.putArray("events").addObject().put("at", 0.2).put("do", "move").put("object", box.id()).put("x", x).put("z", z);
        SimWorld w = SimWorld.parse(tree.toString(), "navigation-moved.json");
        var robot = w.robots().get(0);
        var boxesAtStart = RobotTap.fixedBoxes(w);
        assertTrue(RobotTap.view(w, robot, List.of(), List.of(), boxesAtStart).objects().stream()
                .noneMatch(p -> p.id().equals(box.id())), box.id() + " in the view before it moved");
        w.step(400);
        var placed = RobotTap.view(w, robot, List.of(), List.of(), boxesAtStart).objects().stream().filter(p -> p.id().equals(box.id()))
                .findFirst().orElseThrow(() -> new AssertionError(box.id() + " not in the live view"));
        assertEquals(x, placed.x(), 0.002);
        assertEquals(z, placed.z(), 0.002);
    }

    private static StepLog.Header readHeader(Path dir) throws Exception {
        try (var r = new StepLog.Reader(dir.resolve(StepLog.FILE))) {
            return r.header();
        }
    }
}
