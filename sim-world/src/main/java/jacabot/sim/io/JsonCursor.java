package jacabot.sim.io;

import com.fasterxml.jackson.databind.JsonNode;
import jacabot.sim.geom.Rgb;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

/** A JSON value and its path, with typed accessors that fail with the path. Internal. */
final class JsonCursor {
    /** A check failure before the file name is known; turned into a {@link WorldFileException}. */
    static final class Failure extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final String path;

        Failure(String path, String message) {
            super(message, null, false, false);
            this.path = path;
        }
    }

    final JsonNode json;
    final String path;

    JsonCursor(JsonNode json, String path) {
        this.json = json;
        this.path = path;
    }

    Failure fail(String message) {
        return new Failure(path, message);
    }

    static String describe(JsonNode n) {
        if (n == null || n.isMissingNode()) {
            return "nothing";
        }
        if (n.isNull()) {
            return "null";
        }
        if (n.isNumber()) {
            return "a number";
        }
        if (n.isTextual()) {
            return "a string";
        }
        if (n.isBoolean()) {
            return "a boolean";
        }
        return n.isArray() ? "an array" : "an object";
    }

    /** Requires an object with only the given fields. */
    JsonCursor object(Set<String> known) {
        if (!json.isObject()) {
            throw fail("expected an object, got " + describe(json));
        }
        for (Iterator<String> it = json.fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!known.contains(f)) {
                throw new Failure(path + "." + f, "unknown field (known: " + String.join(", ", new TreeSet<>(known)) + ")");
            }
        }
        return this;
    }

    boolean has(String field) {
        return json.has(field) && !json.get(field).isNull();
    }

    JsonCursor field(String name) {
        if (!has(name)) {
            throw new Failure(path + "." + name, "missing required field");
        }
        return new JsonCursor(json.get(name), path + "." + name);
    }

    List<JsonCursor> array(String name) {
        List<JsonCursor> out = new ArrayList<>();
        if (!has(name)) {
            return out;
        }
        JsonCursor a = field(name);
        if (!a.json.isArray()) {
            throw a.fail("expected an array, got " + describe(a.json));
        }
        for (int i = 0; i < a.json.size(); i++) {
            out.add(new JsonCursor(a.json.get(i), a.path + "[" + i + "]"));
        }
        return out;
    }

    double asNumber() {
        if (!json.isNumber()) {
            throw fail("expected a number, got " + describe(json));
        }
        double v = json.asDouble();
        if (!Double.isFinite(v)) {
            throw fail("expected a finite number");
        }
        return v;
    }

    double number(String name) {
        return field(name).asNumber();
    }

    double number(String name, double dflt) {
        return has(name) ? number(name) : dflt;
    }

    double positive(String name, double dflt) {
        if (!has(name)) {
            return dflt;
        }
        JsonCursor c = field(name);
        double v = c.asNumber();
        if (v <= 0) {
            throw c.fail("must be > 0, got " + v);
        }
        return v;
    }

    double nonNegative(String name, double dflt) {
        if (!has(name)) {
            return dflt;
        }
        JsonCursor c = field(name);
        double v = c.asNumber();
        if (v < 0) {
            throw c.fail("must be >= 0, got " + v);
        }
        return v;
    }

    long integer(String name, long dflt) {
        if (!has(name)) {
            return dflt;
        }
        JsonCursor c = field(name);
        if (!c.json.isIntegralNumber() || !c.json.canConvertToLong()) {
            throw c.fail("expected an integer, got " + describe(c.json) + (c.json.isNumber() ? " with a fraction" : ""));
        }
        return c.json.asLong();
    }

    String string(String name) {
        JsonCursor c = field(name);
        if (!c.json.isTextual()) {
            throw c.fail("expected a string, got " + describe(c.json));
        }
        if (c.json.asText().isBlank()) {
            throw c.fail("must not be empty");
        }
        return c.json.asText();
    }

    String string(String name, String dflt) {
        return has(name) ? string(name) : dflt;
    }

    boolean bool(String name, boolean dflt) {
        if (!has(name)) {
            return dflt;
        }
        JsonCursor c = field(name);
        if (!c.json.isBoolean()) {
            throw c.fail("expected true or false, got " + describe(c.json));
        }
        return c.json.asBoolean();
    }

    Rgb color(String name, Rgb dflt) {
        if (!has(name)) {
            return dflt;
        }
        String text = string(name);
        try {
            return Rgb.parse(text);
        } catch (IllegalArgumentException e) {
            throw field(name).fail(e.getMessage());
        }
    }
}
