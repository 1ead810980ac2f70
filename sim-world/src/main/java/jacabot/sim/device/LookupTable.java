package jacabot.sim.device;

import java.util.ArrayList;
import java.util.List;

/**
 * Webots' {@code lookupTable}: rows of (input, output, noise), inputs increasing. The output for
 * an input is interpolated linearly between rows and held constant beyond the first and last rows;
 * the noise is the standard deviation of a Gaussian noise as a fraction of the output.
 */
public final class LookupTable {
    /** One row: input (e.g. metres), output (raw value), noise (fraction of the output). */
    public record Row(double input, double output, double noise) {
    }

    private final List<Row> rows;

    /** @throws IllegalArgumentException on fewer than two rows or inputs not increasing */
    public LookupTable(List<Row> rows) {
        if (rows.size() < 2) {
            throw new IllegalArgumentException("a lookup table needs at least two rows");
        }
        for (int i = 1; i < rows.size(); i++) {
            if (rows.get(i).input() <= rows.get(i - 1).input()) {
                throw new IllegalArgumentException("lookup table inputs must increase");
            }
        }
        this.rows = List.copyOf(rows);
    }

    /** {@return a table from triples {input, output, noise}} */
    public static LookupTable of(double[]... triples) {
        List<Row> rows = new ArrayList<>();
        for (double[] t : triples) {
            rows.add(new Row(t[0], t[1], t[2]));
        }
        return new LookupTable(rows);
    }

    /** {@return the rows} */
    public List<Row> rows() {
        return rows;
    }

    /** {@return the largest input: a sensor's range} */
    public double maxInput() {
        return rows.get(rows.size() - 1).input();
    }

    /** {@return the interpolated output} */
    public double output(double input) {
        return interpolate(input, true);
    }

    /** {@return the interpolated noise fraction} */
    public double noise(double input) {
        return interpolate(input, false);
    }

    /** {@return the smallest output over the table} */
    public double minOutput() {
        return rows.stream().mapToDouble(Row::output).min().orElseThrow();
    }

    /** {@return the largest output over the table} */
    public double maxOutput() {
        return rows.stream().mapToDouble(Row::output).max().orElseThrow();
    }

    private double interpolate(double input, boolean output) {
        Row first = rows.get(0);
        if (input <= first.input()) {
            return output ? first.output() : first.noise();
        }
        for (int i = 1; i < rows.size(); i++) {
            Row b = rows.get(i);
            if (input <= b.input()) {
                Row a = rows.get(i - 1);
                double t = (input - a.input()) / (b.input() - a.input());
                double va = output ? a.output() : a.noise();
                double vb = output ? b.output() : b.noise();
                return va + t * (vb - va);
            }
        }
        Row last = rows.get(rows.size() - 1);
        return output ? last.output() : last.noise();
    }
}
