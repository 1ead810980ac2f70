package jacabot.agent.syntax;

import java.util.Set;

/**
 * The names of Jason's arithmetic functions: a literal with one of these names and arities is
 * read as a function call in arithmetic positions ({@code X = math.abs(Y)}).
 */
public final class ArithFunctions {
    private static final Set<String> NAMES = Set.of(
            "math.abs/1", "math.sqrt/1", "math.round/1", "math.floor/1", "math.ceil/1",
            "math.max/2", "math.min/2", "math.max/1", "math.min/1", "math.log/1", "math.sin/1", "math.cos/1", "math.tan/1",
            "math.asin/1", "math.acos/1", "math.atan/1", "math.random/0", "math.random/1",
            "math.pi/0", "math.e/0", "math.sum/1", "math.average/1", "math.mean/1", "math.median/1",
            "math.std_dev/1", "math.pow/2", "math.atan2/2", "math.signum/1",
            ".count/1", ".length/1", "system.time/0");

    private ArithFunctions() {
    }

    public static boolean isFunction(String name, int arity) {
        return name.indexOf('.') >= 0 && NAMES.contains(name + "/" + arity);
    }
}
