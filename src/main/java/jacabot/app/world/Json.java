package jacabot.app.world;

import java.util.List;
import java.util.Locale;

/** A small JSON writer: one member per line, arrays one element per line. */
final class Json {
    private final StringBuilder b = new StringBuilder();
    private boolean first = true;

    /** Four decimals: an inner wall's centre lies halfway between two millimetre marks. */
    static String num4(double v) {
        return String.format(Locale.ROOT, "%.4f", v).replaceAll("0+$", "").replaceAll("\\.$", "");
    }

    Json open() {
        b.append("{\n");
        return this;
    }

    private void key(String k) {
        b.append(first ? "" : ",\n").append("  \"").append(k).append("\": ");
        first = false;
    }

    Json field(String k, String text) {
        key(k);
        b.append('"').append(text.replace("\\", "\\\\").replace("\"", "\\\"")).append('"');
        return this;
    }

    Json raw(String k, String json) {
        key(k);
        b.append(json);
        return this;
    }

    Json array(String k, List<String> items) {
        key(k);
        if (items.isEmpty()) {
            b.append("[]");
            return this;
        }
        b.append("[\n");
        for (int i = 0; i < items.size(); i++) {
            b.append("    ").append(items.get(i)).append(i + 1 < items.size() ? ",\n" : "\n");
        }
        b.append("  ]");
        return this;
    }

    String close() {
        return b.append("\n}\n").toString();
    }
}
