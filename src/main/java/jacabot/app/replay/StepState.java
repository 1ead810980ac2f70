package jacabot.app.replay;

import jacabot.app.inspector.MindState;
import jacabot.sim.engine.ObjectState;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The agent's mind and the movable objects rebuilt from a step log, one step after another: a
 * step's changes are applied to the state before it, a key step replaces it. Started from the
 * header (the log's start) or from any key step ({@link StepArchive}).
 */
final class StepState {
    private final Map<String, MindState.Belief> beliefs = new LinkedHashMap<>();
    private List<MindState.IntentionView> intentions = List.of();
    private List<String> events = List.of();
    private long cycle;
    private long seq;
    private Map<String, StepLog.Moved> objects = new LinkedHashMap<>();

    /** Starts from the world as the header has it, with an empty mind. */
    static StepState from(StepLog.Header header) {
        var s = new StepState();
        for (ObjectState o : header.start().objects()) {
            if (o.movable()) {
                s.objects.put(o.id(), new StepLog.Moved(o.pose().x(), o.pose().z(), o.pose().heading(), o.carriedBy()));
            }
        }
        return s;
    }

    /** Applies one step. {@return the agent's mind after it} */
    MindState apply(StepLog.Step s) {
        List<MindState.Selection> selections = List.of();
        var d = s.mind();
        if (s.key()) {
            beliefs.clear();
        }
        if (d != null) {
            cycle = d.cycle();
            if (d.removed() != null) {
                d.removed().forEach(beliefs::remove);
            }
            if (d.added() != null) {
                d.added().forEach(b -> beliefs.put(b.text(), b));
            }
            if (d.intentions() != null) {
                intentions = d.intentions();
            }
            if (d.events() != null) {
                events = d.events();
            }
            if (d.selections() != null) {
                selections = d.selections();
            }
        }
        if (!s.moved().isEmpty()) {
            objects = new LinkedHashMap<>(objects); // frames share the map until something moves
            objects.putAll(s.moved());
        }
        return new MindState("robot", ++seq, s.timeMs(), cycle, new ArrayList<>(beliefs.values()), events, intentions,
                selections);
    }

    /** {@return the movable objects now; not to be changed (the next moving step copies it)} */
    Map<String, StepLog.Moved> objects() {
        return objects;
    }
}
