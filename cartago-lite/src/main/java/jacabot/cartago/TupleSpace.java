package jacabot.cartago;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A Linda tuple space, as CArtAgO's stock {@code TupleSpace}; every workspace has one called
 * {@code blackboard}. {@code out(Name, Args...)} adds the tuple {@code Name(Args...)};
 * {@code in(Name, Args...)} removes a matching tuple and {@code rd(Name, Args...)} reads one,
 * waiting (without holding the artifact) until there is one; {@code inp}/{@code rdp} do not wait
 * and fail when there is none. In a template an unbound variable matches any value and is bound to
 * it; other arguments match equal values (numbers by value). Tuples match oldest first.
 */
public class TupleSpace extends Artifact {
    private record Tuple(String name, Object[] values) {
    }

    private final List<Tuple> tuples = new ArrayList<>();

    @OPERATION
    void out(String name, Object... values) {
        for (int i = 0; i < values.length; i++) {
            if (values[i] instanceof OpFeedbackParam) {
                failed("out: argument " + (i + 2) + " is unbound", "unbound_argument", i + 2);
            }
        }
        tuples.add(new Tuple(name, values.clone()));
        commit();   // wakes waiting in/rd
    }

    @OPERATION
    void in(String name, Object... template) {
        await("hasMatch", name, template);
        take(name, template, true);
    }

    @OPERATION
    void rd(String name, Object... template) {
        await("hasMatch", name, template);
        take(name, template, false);
    }

    @OPERATION
    void inp(String name, Object... template) {
        if (!take(name, template, true)) {
            failed("no tuple matches " + name + Arrays.toString(template), "no_match", name);
        }
    }

    @OPERATION
    void rdp(String name, Object... template) {
        if (!take(name, template, false)) {
            failed("no tuple matches " + name + Arrays.toString(template), "no_match", name);
        }
    }

    @GUARD
    boolean hasMatch(String name, Object[] template) {
        return find(name, template) != null;
    }

    private boolean take(String name, Object[] template, boolean remove) {
        Tuple t = find(name, template);
        if (t == null) {
            return false;
        }
        if (remove) {
            tuples.remove(t);
        }
        for (int i = 0; i < template.length; i++) {
            if (template[i] instanceof OpFeedbackParam<?> out) {
                @SuppressWarnings("unchecked")
                OpFeedbackParam<Object> o = (OpFeedbackParam<Object>) out;
                o.set(t.values()[i]);
            }
        }
        return true;
    }

    private Tuple find(String name, Object[] template) {
        for (Tuple t : tuples) {
            if (t.name().equals(name) && t.values().length == template.length && matches(t.values(), template)) {
                return t;
            }
        }
        return null;
    }

    private static boolean matches(Object[] values, Object[] template) {
        for (int i = 0; i < template.length; i++) {
            if (!(template[i] instanceof OpFeedbackParam) && !Values.same(template[i], values[i])) {
                return false;
            }
        }
        return true;
    }
}
