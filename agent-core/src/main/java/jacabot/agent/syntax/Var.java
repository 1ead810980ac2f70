package jacabot.agent.syntax;

import java.util.function.Consumer;

/**
 * A variable. Source variables have serial 0; unnamed variables ({@code _}) and the fresh
 * variables made at run time carry a serial that keeps them apart from every other variable.
 */
public record Var(String name, long serial) implements Term {
    public Var(String name) {
        this(name, 0);
    }

    /** {@return whether the variable is unnamed ({@code _}, {@code _X} or fresh)} */
    public boolean isUnnamed() {
        return serial != 0 || name.startsWith("_");
    }

    // written out, with the values the record's would have: unifiers compare variables all the time
    @Override
    public boolean equals(Object o) {
        return o instanceof Var v && v.serial == serial && v.name.equals(name);
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + Long.hashCode(serial);
    }

    @Override
    public boolean isGround() {
        return false;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        sink.accept(this);
    }

    @Override
    public String toString() {
        if (serial == 0) {
            return name;
        }
        return "_" + Math.abs(serial); // as Jason's (short) unnamed variables
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitVar(this);
    }
}
