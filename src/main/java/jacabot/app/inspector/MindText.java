package jacabot.app.inspector;

import java.io.PrintStream;

/** An agent's mind as console text: what {@code replay --at} and a breakpoint print. */
public final class MindText {
    private MindText() {
    }

    /** Prints beliefs, intentions (top first, with the step about to run), events and the plans just selected. */
    public static void print(MindState m, PrintStream out) {
        out.printf("Mind at t=%.2f s (cycle %d):%n  beliefs:%n", m.timeMs() / 1000.0, m.cycle());
        m.beliefs().forEach(b -> out.println("    " + b.text()));
        out.println("  intentions:");
        for (MindState.IntentionView iv : m.intentions()) {
            out.println("    intention " + iv.id() + " (" + iv.state() + ")");
            iv.stack().forEach(im -> out.println("      " + im.plan() + "   <- " + im.current()
                    + (im.rest().isEmpty() ? "" : "; " + im.rest())));
        }
        out.println("  events: " + (m.events().isEmpty() ? "none" : String.join(", ", m.events())));
        m.selections().forEach(s -> out.println("  selected: " + s.plan() + " for " + s.event() + " " + s.unifier()));
    }
}
