package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TermMapper;
import jacabot.agent.syntax.Var;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Function;

/** Structural renaming of variables (no evaluation), e.g. to rename a rule or an event apart. */
public final class Renamer {
    private Renamer() {
    }

    /**
     * Renames the variables of {@code t} apart: each distinct variable gets the variable
     * {@code fresh} makes for it, remembered in {@code map} (so that several terms, such as a
     * rule's head and body, share one renaming, and a caller can undo it).
     */
    public static Term renameApart(Term t, Function<Var, Var> fresh, Map<Var, Var> map) {
        if (t.isGround()) {
            return t;
        }
        t.collectVars(v -> map.computeIfAbsent(v, fresh));
        return rename(t, map);
    }

    /** Renames the free variables of {@code t} to fresh variables of the agent. */
    public static Term renameApart(Term t, Agent ag) {
        return renameApart(t, ag::freshVar, new HashMap<>());
    }

    static Term rename(Term t, Map<Var, Var> map) {
        return map(t, v -> map.getOrDefault(v, v));
    }

    /** Replaces every variable with the result of {@code f}. */
    static Term map(Term t, Function<Var, Term> f) {
        return new TermMapper() {
            @Override
            public Term visitVar(Var v) {
                return f.apply(v);
            }
        }.map(t);
    }
}
