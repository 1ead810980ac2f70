package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * {@code .save_agent(File[, Goals])}: writes the agent as AgentSpeak text, as Jason's: its beliefs
 * and rules ({@code source(self)} left out) in the order of Jason's belief base, the goals given as
 * initial goals, then its plans under a comment naming their file. Jason's belief base is a hash
 * map by predicate, so the predicates come in the order of its bins (the order here); Jason also
 * writes the four {@code kqml::} rules of its message plans, which run as Java here.
 */
final class SaveAgent extends DefaultInternalAction {
    SaveAgent() {
        super(".save_agent", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String file = args[0] instanceof StringTerm s ? s.value() : args[0].toString();
        var out = new StringBuilder("// beliefs and rules\n");
        for (BeliefBase.Entry e : inJasonOrder(ag.beliefBase())) {
            if (e.rule() != null) {
                out.append(withoutSelf(e.rule().head())).append(" :- ").append(e.rule().body()).append(".\n");
            } else {
                out.append(withoutSelf(e.literal())).append(".\n");
            }
        }
        out.append("\n\n// initial goals\n");
        if (args.length > 1) {
            for (Term g : list(args[1]).elements()) {
                out.append('!').append(g).append(".\n");
            }
        }
        var byFile = new LinkedHashMap<String, StringBuilder>();
        for (Plan p : ag.planLibrary().plans()) {
            String src = p.source() == null ? "" : p.source().jasonFile();
            byFile.computeIfAbsent(src, f -> new StringBuilder(f.isEmpty() ? "\n\n// plans without file\n\n"
                    : "\n\n// plans from " + f + "\n\n")).append(p).append('\n');
        }
        var end = new StringBuilder("\n");
        byFile.forEach((f, text) -> (f.isEmpty() ? end : out).append(text));
        out.append(end);
        try {
            Files.writeString(Path.of(file), out);
        } catch (IOException e) {
            throw new IaException("internal_action", "cannot write " + file + ": " + e.getMessage());
        }
        return true;
    }

    /**
     * The entries by predicate, namespace after namespace, each namespace's predicates in the order
     * of the bins of Jason's {@code ConcurrentHashMap} keyed by predicate indicators (entries of
     * one bin in order of arrival).
     */
    static List<BeliefBase.Entry> inJasonOrder(BeliefBase bb) {
        var groups = new LinkedHashMap<List<Object>, List<BeliefBase.Entry>>();
        for (BeliefBase.Entry e : bb.all()) {
            Literal l = e.rule() != null ? e.rule().head() : e.literal();
            groups.computeIfAbsent(List.of(nsName(l.ns()), (l.negated() ? "~" : "") + l.functor(), l.arity()),
                    k -> new ArrayList<>()).add(e);
        }
        var out = new ArrayList<BeliefBase.Entry>();
        for (Term ns : bb.namespaces()) {
            String name = nsName(ns instanceof Literal n && !n.isDefaultNsName() ? n : null);
            var mine = new ArrayList<Map.Entry<List<Object>, List<BeliefBase.Entry>>>();
            groups.entrySet().stream().filter(g -> g.getKey().get(0).equals(name)).forEach(mine::add);
            int table = 16;
            while (mine.size() > table * 3 / 4) {
                table *= 2;
            }
            int mask = table - 1;
            mine.sort(Comparator.comparingInt(g -> spread(predicateHash(name, (String) g.getKey().get(1),
                    (Integer) g.getKey().get(2))) & mask));
            mine.forEach(g -> out.addAll(g.getValue()));
        }
        return out;
    }

    private static String nsName(Term ns) {
        return ns == null ? Literal.DEFAULT_NS_NAME : Objects.toString(ns instanceof Literal l ? l.functor() : ns);
    }

    /** Jason's hash of a predicate indicator, its namespace atom's hash as Jason computes it. */
    private static int predicateHash(String ns, String functor, int arity) {
        int d = Literal.DEFAULT_NS_NAME.hashCode();
        int nsHash = ns.equals(Literal.DEFAULT_NS_NAME) ? d : ns.hashCode() + d;
        return 31 * (31 * arity * nsHash) + functor.hashCode();
    }

    private static int spread(int h) {
        return (h ^ (h >>> 16)) & 0x7fffffff;
    }

    private static Literal withoutSelf(Literal l) {
        return l.annots().contains(Literal.SOURCE_SELF)
                ? l.withAnnots(l.annots().stream().filter(a -> !a.equals(Literal.SOURCE_SELF)).toList()) : l;
    }
}
