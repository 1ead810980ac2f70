package jacabot.app.replay;

import jacabot.app.inspector.BeliefList;
import jacabot.app.inspector.MindState;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;

/**
 * The step log's beliefs added and removed from one step to the next, by text: a belief is
 * added when no belief of the last step had its text (in the step's order), a text removed when
 * no belief of this step has it (in the last step's order, each text once). Two captures of the
 * mind probe ({@link BeliefList}) are compared group by group: only the groups whose array is
 * not the last step's are read, where a comparison of the whole lists hashed every belief's text
 * at every step. Any other list is compared whole, with the same answer. Not thread-safe: the
 * writer's thread runs it.
 */
final class BeliefDelta {
    /** The text of each belief seen lately, by identity (the probe shows an unchanged belief as the same object). */
    private IdentityHashMap<MindState.Belief, String> texts = new IdentityHashMap<>();
    /** How many of the last step's beliefs have each text. */
    private final HashMap<String, Integer> counts = new HashMap<>();
    /** The last step's beliefs, or null: none (the first step, or a key step, which holds them all). */
    private List<MindState.Belief> last;

    /** Forgets the last step's beliefs: the next step adds all of its own (a key step). */
    void reset() {
        last = null;
        counts.clear();
    }

    /**
     * Adds to {@code added} the beliefs of {@code now} whose text the last step's did not have, to
     * {@code removed} the last step's texts {@code now} does not have. {@return false, and nothing
     * added, when {@code now} is the last step's list itself (the probe's answer while the belief
     * base did not change)}
     */
    boolean between(List<MindState.Belief> now, List<MindState.Belief> added, List<String> removed) {
        if (now == last) {
            return false;
        }
        if (now instanceof BeliefList n && (last == null || last instanceof BeliefList)) {
            byGroups((BeliefList) last, n, added, removed);
        } else {
            whole(now, added, removed);
        }
        last = now;
        if (texts.size() > 4 * now.size() + 64) {
            var kept = new IdentityHashMap<MindState.Belief, String>(now.size());
            now.forEach(b -> kept.put(b, text(b)));
            texts = kept;
        }
        return true;
    }

    private void whole(List<MindState.Belief> now, List<MindState.Belief> added, List<String> removed) {
        for (MindState.Belief b : now) {
            if (!counts.containsKey(text(b))) {
                added.add(b);
            }
        }
        counts.clear();
        now.forEach(b -> counts.merge(text(b), 1, Integer::sum));
        if (last != null) {
            gone(last, removed, new HashSet<>());
        }
    }

    /** As {@link #whole}, reading only the groups whose array is not in both lists. */
    private void byGroups(BeliefList was, BeliefList now, List<MindState.Belief> added, List<String> removed) {
        int before = was == null ? 0 : was.groups();
        var kept = new boolean[before];
        var fresh = new boolean[now.groups()];
        int next = 0;
        for (int g = 0; g < now.groups(); g++) {
            int at = was == null ? -1 : was.indexOfGroup(now.group(g), next);
            if (at < 0) {
                fresh[g] = true;
            } else {
                kept[at] = true;
                next = at + 1;
            }
        }
        for (int g = 0; g < now.groups(); g++) { // against the last step's texts, before counting this step's
            if (fresh[g]) {
                for (MindState.Belief b : now.group(g)) {
                    if (!counts.containsKey(text(b))) {
                        added.add(b);
                    }
                }
            }
        }
        for (int g = 0; g < now.groups(); g++) {
            if (fresh[g]) {
                for (MindState.Belief b : now.group(g)) {
                    counts.merge(text(b), 1, Integer::sum);
                }
            }
        }
        for (int g = 0; g < before; g++) {
            if (!kept[g]) {
                for (MindState.Belief b : was.group(g)) {
                    counts.computeIfPresent(text(b), (t, c) -> c == 1 ? null : c - 1);
                }
            }
        }
        var said = new HashSet<String>();
        for (int g = 0; g < before; g++) {
            if (!kept[g]) {
                gone(Arrays.asList(was.group(g)), removed, said);
            }
        }
    }

    /** Adds to {@code removed} the texts of {@code beliefs} that no belief has now, each once ({@code said}: those added). */
    private void gone(List<MindState.Belief> beliefs, List<String> removed, HashSet<String> said) {
        for (MindState.Belief b : beliefs) {
            String t = text(b);
            if (!counts.containsKey(t) && said.add(t)) {
                removed.add(t);
            }
        }
    }

    private String text(MindState.Belief b) {
        String t = texts.get(b);
        if (t == null) {
            t = b.text();
            texts.put(b, t);
        }
        return t;
    }
}
