package jacabot.cartago.bridge;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.InternalAction;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import jacabot.cartago.JavaObjects;
import jacabot.cartago.JavaObjects.JavaCallException;
import jacabot.cartago.WorkspaceId;
import java.lang.reflect.Array;
import java.util.ArrayList;
import java.util.List;

/**
 * JaCa's {@code cartago.*} internal actions, which {@link CAgentArch} adds to its agent:
 * <ul>
 * <li>Java data binding: {@code new_obj(ClassName, Params, ?Ref)},
 *     {@code invoke_obj(Ref | ClassName, Method[(Args...)][, ?Result])},
 *     {@code new_array(ClassName, Elems, ?Ref)}, {@code array_to_list(Ref, ?List)}. An object is an
 *     object term (it prints as its {@code toString()}); numbers, strings, booleans and characters
 *     come back as terms; an unbound variable passed in is {@code null}; a {@code null} or
 *     {@code void} result leaves the result variable unbound. Each agent's objects are its own.</li>
 * <li>workspaces: {@code set_current_wsp(WspId)}, {@code current_wsps(?List)}.</li>
 * </ul>
 * A failure (no such class or method, arguments that do not fit, an exception thrown by the
 * call) fails the action with {@code error(ia_failed)} and a message that says which and why.
 */
final class CartagoLibrary {
    private final CartagoEnvironment env;
    private final AgentSession session;

    CartagoLibrary(CartagoEnvironment env, AgentSession session) {
        this.env = env;
        this.session = session;
    }

    void install(Agent agent) {
        agent.addInternalAction("cartago.new_obj", action(3, 3, this::newObj));
        agent.addInternalAction("cartago.invoke_obj", action(2, 3, this::invokeObj));
        agent.addInternalAction("cartago.new_array", action(3, 3, this::newArray));
        agent.addInternalAction("cartago.array_to_list", action(2, 2, this::arrayToList));
        agent.addInternalAction("cartago.set_current_wsp", action(1, 1, this::setCurrentWsp));
        agent.addInternalAction("cartago.current_wsps", action(1, 1, this::currentWsps));
    }

    private interface Body {
        boolean run(Unifier un, Term[] args) throws IaException;
    }

    private static InternalAction action(int min, int max, Body body) {
        return new InternalAction() {
            @Override
            public Object execute(Agent agent, Unifier un, Term[] args) throws IaException {
                return body.run(un, args);
            }

            @Override
            public int minArgs() {
                return min;
            }

            @Override
            public int maxArgs() {
                return max;
            }
        };
    }

    private boolean newObj(Unifier un, Term[] args) throws IaException {
        Class<?> type = load(args[0], "cartago.new_obj");
        Object[] params = javaArgs(list(args[1], "cartago.new_obj").elements());
        try {
            return un.unifies(args[2], new ObjectTerm(JavaObjects.newInstance(type, params)));
        } catch (JavaCallException e) {
            throw failed("cartago.new_obj", e);
        }
    }

    private boolean invokeObj(Unifier un, Term[] args) throws IaException {
        Object target = null;
        Class<?> type;
        if (args[0] instanceof ObjectTerm o && o.value() != null) {
            target = o.value();
            type = target.getClass();
        } else {
            type = load(args[0], "cartago.invoke_obj");
        }
        String method;
        List<Term> params;
        if (args[1] instanceof Literal l && !l.negated()) {
            method = l.functor();
            params = l.args();
        } else if (args[1] instanceof StringTerm s) {
            method = s.value();
            params = List.of();
        } else {
            throw IaException.wrongArguments("cartago.invoke_obj", "the method is an atom or a structure, got " + args[1]);
        }
        Object result;
        try {
            Object[] values = javaArgs(params);
            if (target == null && type == Class.class && method.equals("forName") && values.length == 1
                    && values[0] instanceof String name) {
                // caller-sensitive: through reflection it would search this library's loader, not the project's
                result = JavaObjects.load(name, env.classLoader());
            } else {
                result = JavaObjects.invoke(target, type, method, values);
            }
        } catch (JavaCallException e) {
            throw failed("cartago.invoke_obj", e);
        }
        return args.length < 3 || result == null || un.unifies(args[2], toTerm(result));
    }

    private boolean newArray(Unifier un, Term[] args) throws IaException {
        Class<?> component = load(args[0], "cartago.new_array");
        var values = new ArrayList<Object>(List.of(javaArgs(list(args[1], "cartago.new_array").elements())));
        try {
            return un.unifies(args[2], new ObjectTerm(JavaObjects.newArray(component, values)));
        } catch (JavaCallException e) {
            throw failed("cartago.new_array", e);
        }
    }

    private boolean arrayToList(Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof ObjectTerm o) || o.value() == null || !o.value().getClass().isArray()) {
            throw IaException.wrongArguments("cartago.array_to_list", "expected an array object, got " + args[0]);
        }
        var items = new ArrayList<Term>();
        for (int i = 0; i < Array.getLength(o.value()); i++) {
            Object v = Array.get(o.value(), i);
            items.add(v == null ? new Var("_") : toTerm(v));
        }
        return un.unifies(args[1], ListTerm.of(items));
    }

    private boolean setCurrentWsp(Unifier un, Term[] args) throws IaException {
        Object id = TermConverter.toJava(args[0]);
        if (args[0] instanceof Var) {
            // CArtAgO's own example passes a variable it never bound: the workspace the agent started in
            id = WorkspaceId.local(env.workspace().getName());
        }
        boolean ok = id instanceof WorkspaceId w ? session.makeCurrent(w)
                : id instanceof String name && session.byName(name).map(j -> session.makeCurrent(j.id())).orElse(false);
        if (!ok) {
            throw new IaException("ia_failed", "cartago.set_current_wsp: the agent has not joined workspace " + args[0]);
        }
        return true;
    }

    private boolean currentWsps(Unifier un, Term[] args) {
        var ids = new ArrayList<Term>();
        session.all().forEach(w -> ids.add(TermConverter.toTerm(w.id())));
        return un.unifies(args[0], ListTerm.of(ids));
    }

    private Class<?> load(Term name, String ia) throws IaException {
        String className;
        if (name instanceof StringTerm s) {
            className = s.value();
        } else if (name instanceof Literal l && l.isAtom()) {
            className = l.functor();
        } else {
            throw IaException.wrongArguments(ia, "expected a class name, got " + name);
        }
        try {
            return JavaObjects.load(className, env.classLoader());
        } catch (JavaCallException e) {
            throw failed(ia, e);
        }
    }

    private static ListTerm list(Term t, String ia) throws IaException {
        if (t instanceof ListTerm l) {
            return l;
        }
        throw IaException.wrongArguments(ia, "expected a list of arguments, got " + t);
    }

    /** Arguments as Java values; an unbound variable is null. */
    private static Object[] javaArgs(List<Term> terms) {
        Object[] out = new Object[terms.size()];
        for (int i = 0; i < out.length; i++) {
            Term t = terms.get(i);
            out[i] = t instanceof Var ? null : TermConverter.toJava(t);
        }
        return out;
    }

    /** Data come back as terms; any other object as an object term (arrays and collections too). */
    private static Term toTerm(Object v) {
        if (v instanceof Number n) {
            return new NumberTerm(n.doubleValue());
        }
        if (v instanceof String || v instanceof Boolean || v instanceof Character) {
            return TermConverter.toTerm(v);
        }
        return new ObjectTerm(v);
    }

    private static IaException failed(String ia, JavaCallException e) {
        return new IaException("ia_failed", ia + ": " + e.getMessage());
    }
}
