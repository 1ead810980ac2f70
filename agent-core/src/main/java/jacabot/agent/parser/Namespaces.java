package jacabot.agent.parser;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The namespaces one file is read in, as Jason's parser keeps them (Jason's modules):
 * <ul>
 * <li>the current namespace, of the literals written as formulas (beliefs, initial goals,
 * triggers, context and body literals; arguments and list elements are in the default namespace
 * unless prefixed): the one the file was included into, or the one of a
 * {@code { begin namespace(ns) }} block;</li>
 * <li>the namespace {@code ::b} and the atom {@code this_ns} name;</li>
 * <li>the local namespaces ({@code namespace(ns, local)}): each file read gives them names of
 * their own, {@code #Nns}, so that two includes of a module do not share them.</li>
 * </ul>
 * Null stands for the default namespace.
 */
final class Namespaces {
    /**
     * Numbers local namespaces and anonymous includes: Jason's counter is the JVM's, ours the
     * parser's (one per multi-agent system), so a run's names do not depend on earlier runs.
     */
    private final AtomicInteger counter;

    /** Jason's keywords: always in the default namespace, wherever they are written. */
    private static final Set<String> KEYWORDS = Set.of("atomic/0", "breakpoint/0", "all_unifs/0", "default/0",
            "this_ns/0", "source/1", "self/0", "percept/0", "tell/0", "untell/0", "achieve/0", "unachieve/0",
            "askOne/0", "askAll/0", "askHow/0", "tellHow/0", "untellHow/0");

    private Term current;
    private Term thisNs;
    private final Map<String, Literal> local = new HashMap<>();
    private final Deque<Term> outer = new ArrayDeque<>();

    /** @param ns the namespace the file is read in (null: the default one) */
    Namespaces(Term ns, AtomicInteger counter) {
        this.counter = counter;
        current = ns;
        thisNs = ns;
    }

    /** {@return the namespace of literals written as formulas} */
    Term current() {
        return current;
    }

    /** {@return the namespace {@code ::b} names} */
    Term thisNs() {
        return thisNs;
    }

    /** {@return the atom {@code this_ns} stands for} */
    Term thisNsAtom() {
        return thisNs == null ? Literal.DEFAULT_NS : thisNs;
    }

    static boolean isKeyword(String functor, int arity) {
        return KEYWORDS.contains(functor + "/" + arity);
    }

    /** {@return a namespace's name in this file: its unique name when it was declared local} */
    Term map(Term ns) {
        if (ns instanceof Literal l && l.isAtom()) {
            Literal unique = local.get(l.functor());
            if (unique != null) {
                return unique;
            }
        }
        return ns;
    }

    /** {@return a new namespace for {@code include(file, Var)}} */
    static Literal fresh(AtomicInteger counter) {
        return Literal.atom("ns" + counter.incrementAndGet());
    }

    /**
     * Opens {@code namespace(ns[, local|global])}: the literals up to the matching {@link #end}
     * are in ns. {@return an error message, or null}
     */
    String begin(Literal directive) {
        if (directive.arity() < 1 || directive.arity() > 2 || !(directive.arg(0) instanceof Literal name) || !name.isAtom()) {
            return "the namespace directive needs an atom and optionally local or global: '" + directive + "'";
        }
        Term ns = Literal.atom(name.functor());
        if (directive.arity() == 2) {
            String type = directive.arg(1) instanceof Literal t && t.isAtom() ? t.functor() : "";
            if (type.equals("local")) {
                ns = local.computeIfAbsent(name.functor(),
                        n -> Literal.atom(Literal.LOCAL_NS_PREFIX + counter.incrementAndGet() + n));
            } else if (type.equals("global")) {
                local.remove(name.functor());
            } else {
                return "the second argument of the namespace directive must be local or global, not '" + directive.arg(1) + "'";
            }
        }
        outer.push(current == null ? Literal.DEFAULT_NS : current);
        current = ns;
        thisNs = ns;
        return null;
    }

    /** Closes the innermost {@link #begin}: back to the namespace before it (also for {@code ::b}, as Jason). */
    void end() {
        if (!outer.isEmpty()) {
            Term ns = outer.pop();
            current = ns instanceof Literal l && l.isDefaultNsName() ? null : ns;
            thisNs = current;
        }
    }
}
