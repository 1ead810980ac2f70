package jacabot.app.replay;

import static jacabot.app.replay.StepLog.CHUNK;
import static jacabot.app.replay.StepLog.JSON;
import static jacabot.app.replay.StepLog.reading;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectWriter;
import com.fasterxml.jackson.databind.SerializationFeature;
import jacabot.app.inspector.MindState;
import jacabot.app.replay.StepLog.Body;
import jacabot.app.replay.StepLog.Chunk;
import jacabot.app.replay.StepLog.Header;
import jacabot.app.replay.StepLog.Lag;
import jacabot.app.replay.StepLog.MindDelta;
import jacabot.app.replay.StepLog.Moved;
import jacabot.app.replay.StepLog.Pending;
import jacabot.app.replay.StepLog.Step;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import java.io.ByteArrayOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.stream.Collectors;
import java.util.zip.GZIPOutputStream;

/**
 * Turns steps into the file's bytes: the JSON lines, the mind's and the objects' changes, the
 * gzip members. Not thread-safe: the writer's thread runs it.
 */
final class StepEncoder implements Closeable {
    /** The member buffer's usual capacity; one grown past {@link #CHUNK_KEPT} (deep intention stacks) is let go after it. */
    private static final int CHUNK_BUFFER = 1 << 16;
    private static final int CHUNK_KEPT = 1 << 20;
    /** The step log's mapper, for values inside a line being written (no flush after each). */
    private static final ObjectWriter VALUES = JSON.writer().without(SerializationFeature.FLUSH_AFTER_WRITE_VALUE);
    private final OutputStream file;
    /** A gzip member's text before compression: its capacity is that of the largest member so far, unless let go. */
    private ByteArrayOutputStream chunk = new ByteArrayOutputStream(CHUNK_BUFFER);
    private long offset;
    private long steps;
    private long chunkFirstTime;
    private long lastTime;
    volatile Consumer<Chunk> onChunk = c -> {
    };
    volatile Consumer<Step> onStep;
    private final BeliefDelta beliefs = new BeliefDelta();
    private List<MindState.IntentionView> intentions = List.of();
    private List<String> events = List.of();
    private final Map<String, Moved> objects = new HashMap<>();
    /** Walls and boxes where the header has them: they stand still unless the world file's events move one. */
    private final Map<String, Moved> fixedAtStart = new HashMap<>();
    /** The last camera image written (the link's own array, never changed) and its text. */
    private int[] image;
    private String imageText;

    StepEncoder(Path file, Header header) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        this.file = Files.newOutputStream(file);
        for (ObjectState o : header.start().objects()) {
            Moved at = moved(o);
            objects.put(o.id(), at);
            if (!o.movable()) {
                fixedAtStart.put(o.id(), at);
            }
        }
        line(JSON.valueToTree(header));
        flushChunk();
    }

    /** Writes one step, its commands and readings as text (the writer's thread makes that text). */
    void write(Pending s) {
        long timeMs = s.timeMs();
        Body body = s.body();
        boolean key = steps % CHUNK == 0;
        List<String> commands = s.commands().stream().map(Object::toString).collect(Collectors.toList());
        List<String> readings = new ArrayList<>(s.readings().size());
        Consumer<Step> stepSink = onStep;
        // the readings as a reader gives them back, a "same" image resolved (for the sink)
        List<String> resolved = stepSink == null ? null : new ArrayList<>(s.readings().size());
        for (Object r : s.readings()) {
            String text;
            boolean same = false;
            if (r instanceof SensorInfo info && info.kind().orElse(null) == SensorKind.CAMERA_IMAGE) {
                same = !key && image != null && Arrays.equals(info.getIntValues(), image);
                if (!same) {
                    image = info.getIntValues();
                    imageText = reading(info);
                }
                text = imageText;
            } else {
                text = r instanceof SensorInfo info ? reading(info) : (String) r;
            }
            readings.add(same ? ImageText.SAME : text);
            if (resolved != null) {
                resolved.add(text);
            }
        }
        MindState mind = s.mind();
        List<ObjectState> world = s.world();
        Lag lag = s.lag();
        if (key) {
            chunkFirstTime = timeMs;
            beliefs.reset(); // a key step holds the whole mind, and every movable object
            intentions = null;
            events = null;
            objects.clear();
            objects.putAll(fixedAtStart); // a key step holds the walls and boxes an event moved, not the others
        }
        lastTime = timeMs;
        Map<String, Moved> movedNow = stepSink == null ? null : new LinkedHashMap<>();
        MindDelta written = null;
        // streamed field by field, as a tree of the same fields would print (no tree made per step)
        try (JsonGenerator g = JSON.getFactory().createGenerator(chunk)) {
            g.writeStartObject();
            g.writeNumberField("t", timeMs);
            if (key) {
                g.writeBooleanField("key", true);
            }
            g.writeFieldName("body");
            VALUES.writeValue(g, body);
            strings(g, "cmd", commands);
            strings(g, "in", readings);
            if (world != null) {
                boolean anyMoved = false;
                for (ObjectState o : world) {
                    if (o.kind() == ObjectKind.ROBOT || !o.movable() && samePlace(o, objects.get(o.id()))) {
                        continue; // the robot's pose is in its body; a wall or box where it was
                    }
                    Moved now = moved(o);
                    if (!now.equals(objects.get(o.id()))) {
                        objects.put(o.id(), now);
                        if (!anyMoved) {
                            g.writeObjectFieldStart("moved");
                            anyMoved = true;
                        }
                        g.writeFieldName(o.id());
                        VALUES.writeValue(g, now);
                        if (movedNow != null) {
                            movedNow.put(o.id(), now);
                        }
                    }
                }
                if (anyMoved) {
                    g.writeEndObject();
                }
            }
            if (mind != null) {
                MindDelta d = delta(mind);
                if (d.added() != null || d.removed() != null || d.selections() != null || d.intentions() != null
                        || d.events() != null) {
                    g.writeFieldName("mind");
                    VALUES.writeValue(g, d);
                    written = d;
                }
            }
            if (lag != null) {
                g.writeFieldName("lag");
                VALUES.writeValue(g, lag);
            }
            g.writeEndObject();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        chunk.write('\n');
        if (stepSink != null) {
            stepSink.accept(new Step(timeMs, body, commands, resolved, movedNow, written, lag, key));
        }
        steps++;
        if (steps % CHUNK == 0) {
            flushChunk();
        }
    }

    /** Compresses the steps gathered into one gzip member, appends it to the file and announces it. */
    private void flushChunk() {
        if (chunk.size() == 0) {
            return;
        }
        try {
            var member = new ByteArrayOutputStream(chunk.size() / 4 + 64);
            try (var gz = new GZIPOutputStream(member, 1 << 16)) {
                chunk.writeTo(gz);
            }
            file.write(member.toByteArray());
            file.flush();
            long first = steps == 0 ? -1 : (steps - 1) / CHUNK * CHUNK;
            Chunk c = new Chunk(offset, first, first < 0 ? -1 : chunkFirstTime, lastTime);
            offset += member.size();
            if (chunk.size() > CHUNK_KEPT) {
                chunk = new ByteArrayOutputStream(CHUNK_BUFFER); // a 10-minute run kept a 16 MB buffer after one such stretch
            } else {
                chunk.reset();
            }
            if (first >= 0) {
                onChunk.accept(c);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Whether {@code o} stands where {@code last} has it, without a record made per wall and step. */
    private static boolean samePlace(ObjectState o, Moved last) {
        return last != null && o.pose().x() == last.x() && o.pose().z() == last.z() && o.pose().heading() == last.heading();
    }

    private static Moved moved(ObjectState o) {
        return new Moved(o.pose().x(), o.pose().z(), o.pose().heading(), o.carriedBy());
    }

    private MindDelta delta(MindState mind) {
        var added = new ArrayList<MindState.Belief>();
        var removed = new ArrayList<String>();
        beliefs.between(mind.beliefs(), added, removed);
        List<MindState.IntentionView> ints = mind.intentions().equals(intentions) ? null : mind.intentions();
        intentions = mind.intentions();
        List<String> evs = mind.events().equals(events) ? null : mind.events();
        events = mind.events();
        return new MindDelta(mind.cycle(), added.isEmpty() ? null : added, removed.isEmpty() ? null : removed,
                mind.selections().isEmpty() ? null : mind.selections(), ints, evs);
    }

    /** Writes {@code name: [texts]}, or nothing for no text. */
    private static void strings(JsonGenerator g, String name, List<String> texts) throws IOException {
        if (texts.isEmpty()) {
            return;
        }
        g.writeArrayFieldStart(name);
        for (String t : texts) {
            g.writeString(t);
        }
        g.writeEndArray();
    }

    private void line(JsonNode n) {
        try {
            JSON.writeValue(chunk, n);
            chunk.write('\n');
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void close() throws IOException {
        try {
            flushChunk();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        } finally {
            file.close();
        }
    }
}
