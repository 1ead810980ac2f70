package jacabot.app.inspector;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The inspector's views over time, built from an agent's minds in time order: the intention
 * timeline (which plan ran on top of which intention, from when to when: a Gantt chart of the
 * run), a belief's history (each time a belief of that name was added or removed), and the
 * artifacts an agent perceives at one instant (its observable properties, grouped by artifact
 * through the {@code artifact_name} annotation CArtAgO puts on them).
 */
public final class TimeViews {
    /** At most this many bars in a timeline (the longest run then loses its shortest bars). */
    static final int MAX_SPANS = 20_000;

    private TimeViews() {
    }

    /** A plan on top of an intention's stack from {@code fromMs} to {@code toMs} (the last mind's time when still there). */
    public record Span(int intention, String plan, long fromMs, long toMs) {
    }

    /** A belief added ({@code +}) or removed ({@code -}) at an instant. */
    public record Change(long timeMs, char sign, String belief) {
    }

    /** Builds the intention timeline, mind after mind. */
    public static final class Timeline {
        private final Map<String, Long> open = new LinkedHashMap<>();
        private final List<Span> done = new ArrayList<>();
        private long last;

        /** Takes the next mind (in time order). */
        public void add(MindState m) {
            var now = new HashMap<String, Boolean>();
            for (MindState.IntentionView i : m.intentions()) {
                if (!i.stack().isEmpty()) {
                    now.put(i.id() + "\u0000" + i.stack().get(0).plan(), true);
                }
            }
            var it = open.entrySet().iterator();
            while (it.hasNext()) {
                var e = it.next();
                if (!now.containsKey(e.getKey())) {
                    close(e.getKey(), e.getValue(), m.timeMs());
                    it.remove();
                }
            }
            now.keySet().forEach(k -> open.putIfAbsent(k, m.timeMs()));
            last = m.timeMs();
        }

        private void close(String key, long from, long to) {
            int cut = key.indexOf('\u0000');
            done.add(new Span(Integer.parseInt(key.substring(0, cut)), key.substring(cut + 1), from, to));
        }

        /** {@return the bars so far, the open ones ending at the last mind, longest kept when there are too many} */
        public List<Span> spans() {
            var out = new ArrayList<>(done);
            open.forEach((k, from) -> {
                int cut = k.indexOf('\u0000');
                out.add(new Span(Integer.parseInt(k.substring(0, cut)), k.substring(cut + 1), from, last));
            });
            if (out.size() > MAX_SPANS) {
                out.sort((a, b) -> Long.compare(b.toMs() - b.fromMs(), a.toMs() - a.fromMs()));
                out.subList(MAX_SPANS, out.size()).clear();
            }
            out.sort((a, b) -> a.fromMs() != b.fromMs() ? Long.compare(a.fromMs(), b.fromMs()) : Integer.compare(a.intention(), b.intention()));
            return out;
        }
    }

    /** Builds a belief's history, mind after mind: the beliefs whose literal is {@code name} or starts with {@code name(}. */
    public static final class BeliefHistory {
        private final String name;
        private Set<String> held = new TreeSet<>();
        private final List<Change> changes = new ArrayList<>();

        public BeliefHistory(String name) {
            this.name = name.trim();
        }

        public void add(MindState m) {
            var now = new TreeSet<String>();
            for (MindState.Belief b : m.beliefs()) {
                if (b.literal().equals(name) || b.literal().startsWith(name + "(")) {
                    now.add(b.literal());
                }
            }
            for (String b : held) {
                if (!now.contains(b)) {
                    changes.add(new Change(m.timeMs(), '-', b));
                }
            }
            for (String b : now) {
                if (!held.contains(b)) {
                    changes.add(new Change(m.timeMs(), '+', b));
                }
            }
            held = now;
            if (changes.size() > MAX_SPANS) {
                changes.subList(0, changes.size() - MAX_SPANS).clear();
            }
        }

        public List<Change> changes() {
            return List.copyOf(changes);
        }
    }

    /** {@return the artifacts {@code m}'s agent perceives: each one's observable properties, by artifact name} */
    public static Map<String, List<String>> artifacts(MindState m) {
        var out = new TreeMap<String, List<String>>();
        for (MindState.Belief b : m.beliefs()) {
            if (!b.isPercept()) {
                continue;
            }
            String artifact = "(no artifact: a percept of the environment)";
            for (String a : b.annots()) {
                if (a.startsWith("artifact_name(\"") && a.endsWith("\")")) {
                    artifact = a.substring(15, a.length() - 2);
                }
            }
            out.computeIfAbsent(artifact, k -> new ArrayList<>()).add(b.literal());
        }
        return out;
    }
}
