package jacabot.app.inspector;

import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.StepList;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * The intentions section of a {@link MindState}, printed only where an intended means changed.
 * An intended means' trigger and plan never change, its steps are an immutable list (a new one
 * when it moves on) and its unifier's bindings are immutable terms: one whose steps object,
 * unifier object and bindings are those of the last capture is shown as the same {@link
 * MindState.Means}, an intention all of whose means are unchanged as the same view, and the list
 * as the same list when no view changed. The text of a step list, {@code a; b; c}, is kept by
 * list object, so an intended means that moved on one step is printed from its rest's text. An
 * object term (its Java object may change, as a loop's saved unifier) is printed at every
 * capture. Not thread-safe: the agent's thread captures.
 */
final class IntentionTexts {
    /** Step lists and plan heads whose text is kept at most; past this the memory starts anew. */
    static final int MEMO = 4096;

    /** A step list's text: its first step's, and all of them joined as {@code a; b; c}. */
    private record Chain(String head, String joined, boolean stable) {
    }

    private record Head(String text, boolean stable) {
    }

    /** An intended means as the last capture showed it, and what it was made of. */
    private record Seen(StepList steps, Unifier unifier, Object[] bindings, boolean stable, String trigger,
            boolean triggerStable, String unifierText, boolean unifierStable, MindState.Means means) {
    }

    private IdentityHashMap<IntendedMeans, Seen> seen = new IdentityHashMap<>();
    private IdentityHashMap<Intention, MindState.IntentionView> views = new IdentityHashMap<>();
    private IdentityHashMap<Term, String> reasons = new IdentityHashMap<>();
    private final IdentityHashMap<StepList, Chain> chains = new IdentityHashMap<>();
    private final IdentityHashMap<Plan, Head> heads = new IdentityHashMap<>();
    private List<MindState.IntentionView> last = List.of();

    /** {@return every intention, by id, each with its stack of intended means (top first) and its state} */
    List<MindState.IntentionView> of(Circumstance c) {
        var pendingReason = new HashMap<Intention, String>();
        var reasonsNow = new IdentityHashMap<Term, String>();
        for (Map.Entry<String, Circumstance.Pending> p : c.pendingIntentions().entrySet()) {
            Term reason = p.getValue().reason();
            String text = reasons.get(reason);
            if (text == null) {
                text = "waiting: " + reason;
            }
            if (StableText.of(reason)) {
                reasonsNow.put(reason, text);
            }
            pendingReason.put(p.getValue().intention(), text);
        }
        reasons = reasonsNow;
        var seenNow = new IdentityHashMap<IntendedMeans, Seen>();
        var viewsNow = new IdentityHashMap<Intention, MindState.IntentionView>();
        var intentions = new ArrayList<MindState.IntentionView>();
        for (Intention i : c.allIntentions()) {
            MindState.IntentionView was = views.get(i);
            boolean same = was != null && was.stack().size() == i.size();
            var stack = new ArrayList<MindState.Means>(i.size());
            int k = 0;
            for (IntendedMeans im : i) {
                Seen s = see(im, seen.get(im));
                seenNow.put(im, s);
                same = same && was.stack().get(k) == s.means();
                stack.add(s.means());
                k++;
            }
            String state = pendingReason.getOrDefault(i,
                    i.isSuspended() ? "suspended" : c.hasRunningIntention(i) ? "running" : "waiting");
            MindState.IntentionView view = same && was.state().equals(state) ? was
                    : new MindState.IntentionView(i.id(), state, stack);
            viewsNow.put(i, view);
            intentions.add(view);
        }
        seen = seenNow;
        views = viewsNow;
        intentions.sort(Comparator.comparingInt(MindState.IntentionView::id));
        if (!sameObjects(intentions, last)) {
            last = List.copyOf(intentions);
        }
        return last;
    }

    private static boolean sameObjects(List<?> a, List<?> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            if (a.get(i) != b.get(i)) {
                return false;
            }
        }
        return true;
    }

    /** {@return the intended means as shown now: as before when nothing of it changed} */
    private Seen see(IntendedMeans im, Seen was) {
        StepList steps = im.steps();
        Unifier u = im.unifier();
        boolean sameUnifier = was != null && was.unifierStable() && was.unifier() == u && u.hasBindings(was.bindings());
        if (sameUnifier && was.stable() && was.steps() == steps) {
            return was;
        }
        String trigger;
        boolean triggerStable;
        if (was != null && was.triggerStable()) {
            trigger = was.trigger(); // an intended means' trigger never changes
            triggerStable = true;
        } else {
            trigger = im.trigger().toString();
            triggerStable = StableText.of(im.trigger().literal());
        }
        Object[] bindings;
        String unifier;
        boolean unifierStable;
        if (sameUnifier) {
            bindings = was.bindings();
            unifier = was.unifierText();
            unifierStable = true;
        } else {
            bindings = u.bindingsNow();
            unifier = u.toString();
            unifierStable = stable(u);
        }
        Head head = head(im.plan());
        String current = "";
        String all = "";
        boolean stepsStable = true;
        if (steps != null) {
            Chain c = chain(steps);
            current = c.head();
            stepsStable = c.stable();
            all = remainingBody(steps);
        }
        String rest = all.startsWith(current) ? dropSeparator(all.substring(current.length())) : all;
        var means = new MindState.Means(trigger, head.text(), unifier, current, rest);
        if (was != null && means.equals(was.means())) {
            means = was.means(); // printed anew, the same text: the same object
        }
        boolean stable = triggerStable && unifierStable && head.stable() && stepsStable;
        return new Seen(steps, u, bindings, stable, trigger, triggerStable, unifier, unifierStable, means);
    }

    private static boolean stable(Unifier u) {
        for (Term t : u.bindings().values()) {
            if (!StableText.of(t)) {
                return false;
            }
        }
        return true;
    }

    /** {@return {@code s} without a leading {@code ;} and the white space after it, as {@code replaceFirst("^;\\s*", "")}} */
    static String dropSeparator(String s) {
        if (s.isEmpty() || s.charAt(0) != ';') {
            return s;
        }
        int i = 1;
        while (i < s.length() && " \t\n\u000B\f\r".indexOf(s.charAt(i)) >= 0) {
            i++;
        }
        return s.substring(i);
    }

    /**
     * {@return the steps as {@link IntendedMeans#remainingBody()} prints them: joined by {@code ; },
     * a step printing nothing adding no separator while nothing came before it}
     */
    private String remainingBody(StepList steps) {
        for (StepList s = steps; s != null; s = s.next()) {
            Chain c = chain(s);
            if (!c.head().isEmpty()) {
                return c.joined();
            }
        }
        return "";
    }

    /** {@return the text of a step list, from the kept text of its longest known rest} */
    private Chain chain(StepList steps) {
        Chain known = chains.get(steps);
        if (known != null) {
            return known;
        }
        var todo = new ArrayList<StepList>();
        Chain below = null;
        for (StepList s = steps; s != null && (below = chains.get(s)) == null; s = s.next()) {
            todo.add(s);
        }
        for (int k = todo.size() - 1; k >= 0; k--) {
            StepList s = todo.get(k);
            String head = s.head().toString();
            boolean stable = StableText.of(s.head()) && (below == null || below.stable());
            below = new Chain(head, below == null ? head : head + "; " + below.joined(), stable);
            if (stable) {
                if (chains.size() >= MEMO) {
                    chains.clear();
                }
                chains.put(s, below);
            }
        }
        return below;
    }

    /** {@return {@code @label +trigger : context}, the plan without its body, kept by plan} */
    String headOf(Plan p) {
        return head(p).text();
    }

    private Head head(Plan p) {
        Head h = heads.get(p);
        if (h == null) {
            h = new Head(planHead(p), StableText.of(p.label()) && StableText.of(p.trigger().literal())
                    && StableText.of(p.context()));
            if (h.stable()) {
                if (heads.size() >= MEMO) {
                    heads.clear();
                }
                heads.put(p, h);
            }
        }
        return h;
    }

    /** {@return {@code @label +trigger : context}, the plan without its body} */
    static String planHead(Plan p) {
        var out = new StringBuilder();
        if (p.label() != null) {
            out.append('@').append(p.label().withoutAnnots()).append(' ');
        }
        out.append(p.trigger());
        if (p.context() != null) {
            out.append(" : ").append(p.context());
        }
        return out.toString();
    }
}
