package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The in-process link: each write's whole frames reach the other end before the write returns, through the usual codecs. */
class MemoryLinkTest {
    private static final Protocol.Hello HELLO = new Protocol.Hello(Protocol.VERSION, "khepera", "w", 40, true, List.of());

    /** A middleware end that keeps what it reads, and whether and why the link closed. */
    private static final class Middleware implements MemoryLink.Acceptor {
        final MemoryLink link;
        final List<Uplink> frames = new ArrayList<>();
        final List<String> closed = new ArrayList<>();
        SensorDataReader reader;

        Middleware(MemoryLink link) {
            this.link = link;
        }

        @Override
        public MemoryLink.Reader accept(Protocol.Hello hello) throws IOException {
            reader = new SensorDataReader(link.middlewareIn(), SensorInfoFilter.Limits.DEFAULT);
            return new MemoryLink.Reader() {
                @Override
                public void read(long n) {
                    try {
                        for (long i = 0; i < n; i++) {
                            frames.add(reader.read());
                        }
                    } catch (IOException e) {
                        frames.add(new Uplink.Bye("failed: " + e.getMessage()));
                    }
                }

                @Override
                public void closed(String reason) {
                    closed.add(reason);
                }
            };
        }
    }

    @Test
    void framesArriveWholeAcrossStreamRestartsAndUnflushedOnesWaitForTheNextStep() throws IOException {
        MemoryLink link = new MemoryLink(new Object());
        Middleware m = new Middleware(link);
        link.listen(m);
        List<ReceivedCommand> commands = new ArrayList<>();
        CommandReader commandReader = new CommandReader(link.controllerIn(), () -> 7);
        SensorDataWriter out = new SensorDataWriter(link.controllerOut(), 2); // restarts its object stream every 2 steps
        link.connect(HELLO, out, new MemoryLink.Reader() {
            @Override
            public void read(long n) {
                try {
                    for (long i = 0; i < n; i++) {
                        commands.add(commandReader.read());
                    }
                } catch (IOException e) {
                    throw new AssertionError(e);
                }
            }

            @Override
            public void closed(String reason) {
            }
        });
        List<SensorInfo> readings = LinkFramesTest.everyShape();
        for (int step = 0; step < 5; step++) {
            var batch = new Uplink.Batch(step, 40L * step, 3, readings);
            var marker = new Uplink.StepMarker(step, 40L * step, true);
            link.fromController(w -> w.writeStep(batch, marker));
            assertEquals(List.of(batch, marker), m.frames.subList(m.frames.size() - 2, m.frames.size()), "step " + step);
            var applied = new Uplink.Applied(step, 1, step, 40L * step, 1, 2);
            int before = m.frames.size();
            link.fromController(w -> w.writeApplied(applied, false));
            assertEquals(before, m.frames.size(), "an unflushed frame is not read yet");
            if (step == 4) {
                link.fromController(w -> w.writeBye(new Uplink.Bye("done")));
                assertEquals(List.of(applied, new Uplink.Bye("done")), m.frames.subList(before, m.frames.size()));
            }
        }
        assertEquals(5 * 3 + 1, m.frames.size());

        link.fromMiddleware(w -> w.writeAll(new int[] {1, 2}, 9, List.of(Command.setSpeeds(1, -1), Command.stepAck(4))));
        assertEquals(2, commands.size(), "both commands read before the write returned");
        assertEquals(Command.setSpeeds(1, -1), commands.get(0).command());
        assertEquals(new ReceivedCommand(2, 9, 7, Command.stepAck(4), null), commands.get(1));
    }

    @Test
    void oneConnectionOnlyAndNothingAfterTheClose() throws IOException {
        MemoryLink link = new MemoryLink(new Object());
        SensorDataWriter out = new SensorDataWriter(link.controllerOut(), 10);
        MemoryLink.Reader ignore = new MemoryLink.Reader() {
            @Override
            public void read(long n) {
            }

            @Override
            public void closed(String reason) {
            }
        };
        var nobody = assertThrows(IOException.class, () -> link.connect(HELLO, out, ignore));
        assertTrue(nobody.getMessage().contains("no middleware"), nobody.getMessage());
        Middleware m = new Middleware(link);
        link.listen(m);
        link.connect(HELLO, out, ignore);
        var again = assertThrows(IOException.class, () -> link.connect(HELLO, out, ignore));
        assertTrue(again.getMessage().contains("one connection only"), again.getMessage());
        link.close("done");
        link.close("twice");
        assertEquals(List.of("done"), m.closed, "the end hears the first close once");
        var late = assertThrows(IOException.class, () -> link.fromMiddleware(w -> w.write(1, 0, Command.stop())));
        assertTrue(late.getMessage().contains("closed: done"), late.getMessage());
    }

    @Test
    void aReadBeyondWhatWasWrittenFailsInsteadOfWaiting() throws IOException {
        MemoryLink link = new MemoryLink(new Object());
        Middleware m = new Middleware(link);
        link.listen(m);
        link.connect(HELLO, new SensorDataWriter(link.controllerOut(), 10), new MemoryLink.Reader() {
            @Override
            public void read(long n) {
            }

            @Override
            public void closed(String reason) {
            }
        });
        var e = assertThrows(IOException.class, () -> m.reader.read());
        assertTrue(e.getMessage().contains("never written whole"), e.getMessage());
    }
}
