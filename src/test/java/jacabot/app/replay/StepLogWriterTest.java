package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.MindProbe;
import jacabot.app.inspector.MindState;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.Robot;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The step log written on a thread of its own is the file the step's thread wrote, to the byte;
 * the queue loses no step; a failure of the writing reaches the run when the log closes.
 */
class StepLogWriterTest {
    static final Experiment PICKING = Experiment.parse("object-picking").orElseThrow();

    @Test
    void aRunsStepLogIsTheSameWrittenInTheBackground(@TempDir Path dir) throws Exception {
        var spec = WorldFileReader.read(RunTapTest.ROOT.resolve(PICKING.worldFile()));
        var run = new LockstepRun(SimWorld.of(spec), null, PICKING, AgentSource.packaged(PICKING), 3,
                new PrintStream(OutputStream.nullOutputStream()));
        SimWorld w = run.world();
        Robot robot = w.robots().get(0);
        MindProbe probe = MindProbe.attach(run.mas().agent(run.agentNames().get(0)));
        WorldSnapshot start = w.snapshot();
        var header = new StepLog.Header(StepLog.FORMAT, PICKING.id(), w.name(), w.seed(), w.controlStep(), robot.name(),
                "object-picking.asl", start, null);
        var chunks = new int[2];
        try (var inline = new StepLog.Writer(dir.resolve("inline.jsonl.gz"), header, false);
                var background = new StepLog.Writer(dir.resolve("background.jsonl.gz"), header, true)) {
            inline.onChunk(c -> chunks[0]++);
            background.onChunk(c -> chunks[1]++);
            run.onCommands((data, commands) -> {
                MindState mind = probe.capture();
                var p = robot.pose();
                var body = new StepLog.Body(p.x(), p.z(), p.heading(), robot.hasBattery() ? robot.getBattery().energy() : null,
                        robot.getWheels().getLeftSpeed(), robot.getWheels().getRightSpeed(),
                        robot.hasGripper() ? robot.getGripper().heldObject() : null, robot.contactTime());
                var objects = w.supervisor().objects();
                inline.step(data.simTimeMs(), body, commands, data.readings(), mind, objects);
                background.step(data.simTimeMs(), body, commands, data.readings(), mind, objects);
            });
            run.runFor(12); // 300 steps: more than the queue holds, three gzip members
        }
        byte[] expected = Files.readAllBytes(dir.resolve("inline.jsonl.gz"));
        assertTrue(expected.length > 10_000, "a step log of " + expected.length + " bytes");
        assertArrayEquals(expected, Files.readAllBytes(dir.resolve("background.jsonl.gz")));
        assertEquals(3, chunks[0]);
        assertEquals(chunks[0], chunks[1], "every gzip member announced");
        try (var r = new StepLog.Reader(dir.resolve("background.jsonl.gz"))) {
            int steps = 0;
            while (r.next() != null) {
                steps++;
            }
            assertEquals(300, steps);
        }
    }

    @Test
    void aFailureOfTheWriterThreadSurfacesAtTheNextStepAndAtClose(@TempDir Path dir) throws Exception {
        SyntheticRun.write(dir, 1); // a header to reuse
        StepLog.Header header;
        try (var r = new StepLog.Reader(dir.resolve(StepLog.FILE))) {
            header = r.header();
        }
        var body = new StepLog.Body(0, 0, 0, null, 0, 0, null, 0);
        // the first member's end fails on the writer's thread: the close says so
        var log = failing(dir.resolve("a.jsonl.gz"), header);
        for (long t = 40; t <= 40L * StepLog.CHUNK; t += 40) {
            log.stepText(t, body, List.of(), List.of(), null, null);
        }
        assertEquals("disk full", assertThrows(IOException.class, log::close).getMessage());

        // and so does the next step, once the writer has met it
        var next = failing(dir.resolve("b.jsonl.gz"), header);
        long t = 40;
        for (; t <= 40L * StepLog.CHUNK; t += 40) {
            next.stepText(t, body, List.of(), List.of(), null, null);
        }
        UncheckedIOException failed = null;
        for (long deadline = System.nanoTime() + 10_000_000_000L; failed == null && System.nanoTime() < deadline; t += 40) {
            try {
                next.stepText(t, body, List.of(), List.of(), null, null);
                Thread.sleep(10);
            } catch (UncheckedIOException e) {
                failed = e;
            }
        }
        assertTrue(failed != null && "disk full".equals(failed.getCause().getMessage()), "the step failed: " + failed);
        assertThrows(IOException.class, next::close);
    }

    private static StepLog.Writer failing(Path file, StepLog.Header header) throws IOException {
        return new StepLog.Writer(file, header).onChunk(c -> {
            throw new UncheckedIOException(new IOException("disk full"));
        });
    }
}
