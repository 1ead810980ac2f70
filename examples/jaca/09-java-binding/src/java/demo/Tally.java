package demo;

/** A plain Java object (not an artifact): the agent makes it and calls it with cartago.* actions. */
public class Tally {
    private int total;

    public Tally(int start) {
        total = start;
    }

    public Tally() {
        this(0);
    }

    public void add() {
        total++;
    }

    public void add(int n) {
        total += n;
    }

    public int total() {
        return total;
    }

    public void reset(int to) {
        if (to < 0) {
            throw new IllegalArgumentException("a tally never goes below zero");
        }
        total = to;
    }
}
