package jacabot.app.replay;

import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import jacabot.app.inspector.MindState;
import jacabot.app.run.LagMeter;
import jacabot.robot.link.Command;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import java.io.BufferedReader;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.function.Consumer;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;

/**
 * A run's step log, {@code steps.jsonl.gz}: one JSON line per control step, gzipped and streamed
 * to disk as the run goes (nothing accumulates in memory). The file is a chain of gzip members
 * (which any gzip reader reads as one stream): the header alone, then one member per
 * {@value #CHUNK} steps whose first step is a key step ({@code "key": true}: the whole mind and
 * every movable object, not only their changes), so that {@link StepArchive} can read any instant
 * from the nearest key step without reading the run from its start. The first line is a header with the
 * world as it was at the start; each step then holds the robot's pose, battery and wheel speeds,
 * the commands sent, the readings received, the objects that moved, and the agent's mind as
 * changes: beliefs added and removed, plans selected, and the intentions and events whenever
 * they differ from the step before. {@link Reader} reads it back, step by step.
 */
public final class StepLog {
    public static final String FILE = "steps.jsonl.gz";
    /** The format written: 2 writes the camera image compactly ({@link ImageText}); 1 as decimal text. */
    public static final String FORMAT = "jacabot-steps/2";
    /** The formats read. */
    static final List<String> READS = List.of("jacabot-steps/1", FORMAT);
    /** Steps per gzip member; each member starts with a key step (4 s of a 40 ms control step). */
    public static final int CHUNK = 100;

    static final ObjectMapper JSON = new ObjectMapper().configure(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES, false)
            .setSerializationInclusion(JsonInclude.Include.NON_NULL);

    /** Rounds to 0.1 mm, 0.01 degree, 0.01 J: what the plots and the replay need, in a third of the bytes. */
    static double round(double v) {
        return Double.isFinite(v) ? Math.round(v * 1e4) / 1e4 : v;
    }

    private StepLog() {
    }

    /**
     * Run facts for the header; {@code plans}: the agent's plan library at the start, as the
     * inspector shows it (null: no agent, or not known when the log opened); {@code pacing}:
     * {@value #REAL_TIME} for a real-time run, whose steps cannot be made again step for step
     * (null: lockstep, reproducible under its seed).
     */
    public record Header(String format, String experiment, String world, long seed, int controlStep, String robot,
            String agentFile, WorldSnapshot start, List<String> plans, String pacing) {
        public static final String REAL_TIME = "real-time";

        /** A lockstep run's header. */
        public Header(String format, String experiment, String world, long seed, int controlStep, String robot,
                String agentFile, WorldSnapshot start, List<String> plans) {
            this(format, experiment, world, seed, controlStep, robot, agentFile, start, plans, null);
        }

        /** {@return whether the run was in real time (no what-if from it: it needs a lockstep run's step log)} */
        @JsonIgnore
        public boolean realTime() {
            return REAL_TIME.equals(pacing);
        }
    }

    /** A robot's body in one step. {@code battery} is null without a battery. */
    public record Body(double x, double z, double heading, Double battery, double left, double right, String held,
            double contactTime) {
        public Body {
            x = round(x);
            z = round(z);
            heading = round(heading);
            battery = battery == null ? null : round(battery);
            contactTime = round(contactTime);
        }
    }

    /** A movable object that moved: where it is now and who carries it. */
    public record Moved(double x, double z, double heading, String carriedBy) {
        public Moved {
            x = round(x);
            z = round(z);
            heading = round(heading);
        }
    }

    /**
     * One control step, as read back. {@code mind} holds only what changed, or all of it in a key
     * step; {@code lag} is null but where a lag episode starts or ends.
     */
    public record Step(long timeMs, Body body, List<String> commands, List<String> readings, Map<String, Moved> moved,
            MindDelta mind, Lag lag, boolean key) {
        /** {@return this step with {@code readings} instead of its own (the same step when they are its own)} */
        Step withReadings(List<String> readings) {
            return readings == this.readings ? this
                    : new Step(timeMs, body, commands, readings, moved, mind, lag, key);
        }
    }

    /** A gzip member of steps: where it starts in the file, its first step's number (from 0) and time. */
    public record Chunk(long offset, long firstStep, long firstTimeMs, long lastTimeMs) {
    }

    /**
     * A real-time run's lag episode starting ({@code "start"}) or ending ({@code "end"}) at a step, in
     * simulated ms: how far the world was behind real time, how late the agent was, the speed factor
     * asked for and the one achieved ({@link LagMeter}). Lockstep runs never lag.
     */
    public record Lag(String state, long worldBehindMs, long agentLateMs, double requested, double achieved) {
        public Lag {
            achieved = Double.isFinite(achieved) ? Math.round(achieved * 10) / 10.0 : 0;
        }
    }

    /** The agent's changes in one step; null lists mean "unchanged". */
    public record MindDelta(long cycle, List<MindState.Belief> added, List<String> removed,
            List<MindState.Selection> selections, List<MindState.IntentionView> intentions, List<String> events) {
    }

    // ---- writing ---------------------------------------------------------------------------------------

    /**
     * One step as the run's thread captured it: every part immutable (records, copied lists, the
     * mind's capture, readings and commands as the link made them), so the writer's thread can
     * print it later exactly as it was at the step.
     */
    record Pending(long timeMs, Body body, List<?> commands, List<?> readings, MindState mind,
            List<ObjectState> world, Lag lag) {
    }

    /**
     * Streams steps to a gzipped file. The run's step thread only captures a step and queues it;
     * one writer thread of its own prints, compresses and writes the steps in order, so the file
     * is the same as when the step thread wrote it. The queue is bounded: a step thread that
     * outruns the disk waits (no step is ever dropped). A failure of the writing is thrown by the
     * next step and by {@link #close()}, which writes every queued step first. One thread steps.
     */
    public static final class Writer implements Closeable {
        /** Steps queued at most: a few seconds of simulated time, a few MB of captured minds. */
        static final int QUEUE = 256;
        private static final Pending END = new Pending(-1, null, List.of(), List.of(), null, null, null);

        private final Header header;
        private final StepEncoder encoder;
        private final BlockingQueue<Pending> queue;
        private final Thread thread;
        private volatile Throwable failure;
        private boolean closed;

        public Writer(Path file, Header header) throws IOException {
            this(file, header, true);
        }

        /** @param background false: every step written on the caller's thread (the tests' reference) */
        Writer(Path file, Header header, boolean background) throws IOException {
            this.header = header;
            this.encoder = new StepEncoder(file, header);
            if (background) {
                queue = new ArrayBlockingQueue<>(QUEUE);
                thread = new Thread(this::drain, "step log " + file.getFileName());
                thread.setDaemon(true);
                thread.start();
            } else {
                queue = null;
                thread = null;
            }
        }

        public Header header() {
            return header;
        }

        /**
         * Hands every gzip member of steps, once it is on disk, to {@code sink} (the inspector's
         * index), on the writer's thread. Set it before the first step.
         */
        public Writer onChunk(Consumer<Chunk> sink) {
            encoder.onChunk = sink;
            return this;
        }

        /**
         * Hands every step, as {@link Reader} would read it back, to {@code sink} once it is
         * written, on the writer's thread (the plots' series, collected during the run). Set it
         * before the first step.
         */
        public Writer onStep(Consumer<Step> sink) {
            encoder.onStep = sink;
            return this;
        }

        /**
         * Writes one step.
         *
         * @param mind the agent's mind after the step (null: no agent)
         * @param world the world's objects after the step, to log those that moved
         */
        public void step(long timeMs, Body body, List<Command> commands, List<SensorInfo> readings, MindState mind,
                List<ObjectState> world) {
            submit(new Pending(timeMs, body, List.copyOf(commands), List.copyOf(readings), mind, copy(world), null));
        }

        /**
         * Writes one step whose commands and readings are already text (a real-time run takes them
         * from the controller's event log: {@code KIND=value} readings, the commands it applied).
         */
        public void stepText(long timeMs, Body body, List<String> commands, List<String> readings, MindState mind,
                List<ObjectState> world) {
            stepText(timeMs, body, commands, readings, mind, world, null);
        }

        /** As {@link #stepText(long, Body, List, List, MindState, List)}, with a lag episode's start or end (or null). */
        public void stepText(long timeMs, Body body, List<String> commands, List<String> readings, MindState mind,
                List<ObjectState> world, Lag lag) {
            submit(new Pending(timeMs, body, List.copyOf(commands), List.copyOf(readings), mind, copy(world), lag));
        }

        private static List<ObjectState> copy(List<ObjectState> world) {
            return world == null ? null : List.copyOf(world);
        }

        private void submit(Pending s) {
            if (closed) {
                throw new IllegalStateException("step log closed");
            }
            if (thread == null) {
                encoder.write(s);
                return;
            }
            rethrow();
            uninterruptibly(() -> queue.put(s)); // queued all the same: a step log loses no step
        }

        private interface Wait {
            void run() throws InterruptedException;
        }

        /** Runs {@code w} to its end through interrupts, then interrupts the thread again if it was. */
        private static void uninterruptibly(Wait w) {
            boolean interrupted = false;
            while (true) {
                try {
                    w.run();
                    break;
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }

        /** The writer's thread: writes the queued steps in order until the end; after a failure, only drains. */
        private void drain() {
            while (true) {
                Pending s;
                try {
                    s = queue.take();
                } catch (InterruptedException e) {
                    continue; // nobody interrupts it; the end is a queued mark
                }
                if (s == END) {
                    return;
                }
                if (failure == null) {
                    try {
                        encoder.write(s);
                    } catch (Throwable t) {
                        failure = t;
                    }
                }
            }
        }

        /** Throws the writer thread's failure, if any, on the step's thread. */
        private void rethrow() {
            Throwable t = failure;
            if (t instanceof UncheckedIOException u) {
                throw new UncheckedIOException(u.getMessage(), u.getCause());
            } else if (t instanceof RuntimeException r) {
                throw r;
            } else if (t instanceof Error e) {
                throw e;
            }
        }

        /** Writes every queued step, the last gzip member, and closes the file. */
        @Override
        public void close() throws IOException {
            if (closed) {
                return;
            }
            closed = true;
            try {
                if (thread != null) {
                    uninterruptibly(() -> queue.put(END));
                    uninterruptibly(thread::join);
                    if (failure instanceof UncheckedIOException u) {
                        throw u.getCause();
                    }
                    rethrow();
                }
            } finally {
                encoder.close();
            }
        }
    }

    /**
     * {@return a reading as the step log writes it: {@code KIND value}; the camera image as
     * {@link ImageText#encode} writes it}
     */
    static String reading(SensorInfo s) {
        if (s.kind().orElse(null) == SensorKind.CAMERA_IMAGE) {
            String image = ImageText.encode(s.getIntValues());
            if (image != null) {
                return image;
            }
        }
        var sb = new StringBuilder().append(s.kind().map(Enum::name).orElse("#" + s.getId())).append(' ');
        if (s.getIntValues().length > 0) {
            sb.append(Arrays.toString(s.getIntValues()));
        } else if (s.getCoord()[0] != 0 || s.getCoord()[1] != 0 || s.getCoord()[2] != 0) {
            double[] c = s.getCoord();
            sb.append('[').append(round(c[0])).append(", ").append(round(c[1])).append(", ").append(round(c[2])).append(']');
        } else {
            sb.append(round(s.getVal()));
        }
        return sb.toString();
    }

    // ---- reading ---------------------------------------------------------------------------------------

    /** Reads a step log back, one step at a time. */
    public static final class Reader implements Closeable {
        private final BufferedReader in;
        private final Header header;
        private final Path file;
        private final ImageText.Resolver images = new ImageText.Resolver();
        private long line = 1;

        public Reader(Path file) throws IOException {
            try {
                in = new BufferedReader(new InputStreamReader(new GZIPInputStream(Files.newInputStream(file), 1 << 16),
                        StandardCharsets.UTF_8));
            } catch (ZipException e) {
                throw new IOException(file + ": not a jacabot step log (" + e.getMessage() + ")");
            }
            String first = in.readLine();
            if (first == null) {
                throw new IOException(file + ": empty step log");
            }
            try {
                header = JSON.readValue(first, Header.class);
            } catch (JsonProcessingException e) {
                in.close();
                throw new IOException(file + ":1: not a jacabot step log: " + e.getOriginalMessage());
            }
            if (!READS.contains(header.format())) {
                in.close();
                throw new IOException(file + ":1: not a step log this jacabot reads (format '" + header.format()
                        + "'; it reads " + String.join(" and ", READS) + ")");
            }
            this.file = file;
        }

        public Header header() {
            return header;
        }

        /** {@return the next step, or null at the end} */
        public Step next() throws IOException {
            String text = in.readLine();
            if (text == null) {
                return null;
            }
            line++;
            Step s = parse(text);
            try {
                return s.withReadings(images.resolve(s.readings()));
            } catch (IllegalArgumentException e) {
                throw new IOException(file + ":" + line + ": " + e.getMessage());
            }
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }

    /** {@return a step line read back} */
    static Step parse(String line) throws IOException {
        JsonNode n = JSON.readTree(line);
        var commands = new ArrayList<String>();
        n.path("cmd").forEach(c -> commands.add(c.asText()));
        var readings = new ArrayList<String>();
        n.path("in").forEach(c -> readings.add(c.asText()));
        var moved = new LinkedHashMap<String, Moved>();
        var it = n.path("moved").fields();
        while (it.hasNext()) {
            var e = it.next();
            moved.put(e.getKey(), JSON.treeToValue(e.getValue(), Moved.class));
        }
        MindDelta mind = n.has("mind") ? JSON.treeToValue(n.get("mind"), MindDelta.class) : null;
        Lag lag = n.has("lag") ? JSON.treeToValue(n.get("lag"), Lag.class) : null;
        return new Step(n.get("t").asLong(), JSON.treeToValue(n.get("body"), Body.class), commands, readings, moved, mind,
                lag, n.path("key").asBoolean(false));
    }
}
