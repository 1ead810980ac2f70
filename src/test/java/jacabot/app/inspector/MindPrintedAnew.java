package jacabot.app.inspector;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.syntax.Plan;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;

/**
 * The mind printed from scratch, every belief and intended means anew, as the probe printed it
 * before it kept anything: the reference the kept texts are compared with.
 */
final class MindPrintedAnew {
    private MindPrintedAnew() {
    }

    static List<MindState.Belief> beliefs(Agent agent) {
        var out = new ArrayList<MindState.Belief>();
        for (BeliefBase.Entry e : agent.beliefBase().all()) {
            out.add(e.rule() != null ? new MindState.Belief(e.rule().toString(), List.of(), List.of())
                    : BeliefTexts.belief(e.literal()));
        }
        return out;
    }

    static List<String> events(Agent agent) {
        var out = new ArrayList<String>();
        for (Event e : agent.circumstance().eventList()) {
            out.add(e.trigger().toString() + (e.isExternal() ? "" : "  (intention " + e.intention().id() + ")"));
        }
        return out;
    }

    static List<MindState.IntentionView> intentions(Agent agent) {
        Circumstance c = agent.circumstance();
        var pendingReason = new HashMap<Intention, String>();
        c.pendingIntentions().values().forEach(p -> pendingReason.put(p.intention(), "waiting: " + p.reason()));
        var out = new ArrayList<MindState.IntentionView>();
        for (Intention i : c.allIntentions()) {
            var stack = new ArrayList<MindState.Means>();
            for (IntendedMeans im : i) {
                stack.add(means(im));
            }
            String state = pendingReason.getOrDefault(i,
                    i.isSuspended() ? "suspended" : c.hasRunningIntention(i) ? "running" : "waiting");
            out.add(new MindState.IntentionView(i.id(), state, stack));
        }
        out.sort(Comparator.comparingInt(MindState.IntentionView::id));
        return out;
    }

    private static MindState.Means means(IntendedMeans im) {
        String current = im.currentStep() == null ? "" : im.currentStep().toString();
        String all = im.remainingBody();
        String rest = all.startsWith(current) ? all.substring(current.length()).replaceFirst("^;\\s*", "") : all;
        return new MindState.Means(im.trigger().toString(), planHead(im.plan()), im.unifier().toString(), current, rest);
    }

    private static String planHead(Plan p) {
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
