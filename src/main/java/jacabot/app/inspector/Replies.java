package jacabot.app.inspector;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.io.OutputStream;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;

/** How the inspector's handlers read a request and answer it: never cached, JSON by Jackson. */
final class Replies {
    private static final ObjectMapper JSON = new ObjectMapper();

    private Replies() {
    }

    /** {@return the request's query parameters, decoded (the last of a repeated name)} */
    static Map<String, String> query(HttpExchange ex) {
        var out = new HashMap<String, String>();
        String q = ex.getRequestURI().getRawQuery();
        if (q != null) {
            for (String pair : q.split("&")) {
                int eq = pair.indexOf('=');
                if (eq > 0) {
                    out.put(URLDecoder.decode(pair.substring(0, eq), StandardCharsets.UTF_8),
                            URLDecoder.decode(pair.substring(eq + 1), StandardCharsets.UTF_8));
                }
            }
        }
        return out;
    }

    /** {@return the request's body as text (at most 1 MB: an agent program)} */
    static String body(HttpExchange ex) throws IOException {
        byte[] b = ex.getRequestBody().readNBytes(1 << 20);
        return new String(b, StandardCharsets.UTF_8);
    }

    /** {@return a time given in a query (ms), -1 when missing or not a number} */
    static long time(String text) {
        try {
            return text == null ? -1 : Long.parseLong(text);
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    static String json(Object value) throws IOException {
        return JSON.writeValueAsString(value);
    }

    static void sendText(HttpExchange ex, int status, String text) throws IOException {
        send(ex, status, "text/plain; charset=utf-8", text.getBytes(StandardCharsets.UTF_8));
    }

    static void sendJson(HttpExchange ex, Object value) throws IOException {
        send(ex, 200, "application/json; charset=utf-8", JSON.writeValueAsBytes(value));
    }

    static void send(HttpExchange ex, int status, String type, byte[] body) throws IOException {
        ex.getResponseHeaders().set("Content-Type", type);
        ex.getResponseHeaders().set("Cache-Control", "no-store");
        ex.sendResponseHeaders(status, body.length == 0 ? -1 : body.length);
        try (OutputStream out = ex.getResponseBody()) {
            out.write(body);
        }
    }
}
