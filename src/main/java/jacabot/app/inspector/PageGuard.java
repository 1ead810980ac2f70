package jacabot.app.inspector;

import com.sun.net.httpserver.HttpExchange;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.List;

/**
 * The inspector's guard, as Jupyter's: a request must carry the run's secret token (in the
 * query, or in the cookie the page gets with it), come from no other web page (its
 * {@code Origin}, when sent, is the page's own) and name the inspector's own address as its
 * {@code Host} (no DNS rebinding).
 */
final class PageGuard {
    private final String token = newToken();
    private final InetSocketAddress address;

    PageGuard(InetSocketAddress address) {
        this.address = address;
    }

    String token() {
        return token;
    }

    /** {@return the host the page is addressed by: 127.0.0.1 on loopback} */
    String hostName() {
        InetAddress a = address.getAddress();
        return a.isLoopbackAddress() || a.isAnyLocalAddress() ? "127.0.0.1" : a.getHostAddress();
    }

    /** {@return the cookie header value that gives the page its token for its later requests} */
    String cookie() {
        return cookieName() + "=" + token + "; Path=/; HttpOnly; SameSite=Strict";
    }

    /**
     * {@return why a request is refused, or null: no token or another one, a foreign Origin, a foreign Host}
     *
     * @param given the token in the request's query, or null
     */
    String refusal(HttpExchange ex, String given) {
        int port = address.getPort();
        String origin = ex.getRequestHeaders().getFirst("Origin");
        if (origin != null && !origin.equals("http://" + hostName() + ":" + port) && !origin.equals("http://localhost:" + port)) {
            return "request from another origin (" + origin + ")";
        }
        String host = ex.getRequestHeaders().getFirst("Host");
        if (host != null && !host.equals(hostName() + ":" + port) && !host.equals("localhost:" + port)) {
            return "request for another host (" + host + ")";
        }
        if (given == null) {
            given = cookie(ex);
        }
        if (given == null) {
            return "no token (open the address printed at the start, with its ?token=...)";
        }
        if (!MessageDigest.isEqual(given.getBytes(StandardCharsets.UTF_8), token.getBytes(StandardCharsets.UTF_8))) {
            return "wrong token (another run's?)";
        }
        return null;
    }

    private String cookieName() {
        return "jacabot-inspector-" + address.getPort();
    }

    private String cookie(HttpExchange ex) {
        for (String header : ex.getRequestHeaders().getOrDefault("Cookie", List.of())) {
            for (String c : header.split(";")) {
                String[] kv = c.trim().split("=", 2);
                if (kv.length == 2 && kv[0].equals(cookieName())) {
                    return kv[1];
                }
            }
        }
        return null;
    }

    private static String newToken() {
        byte[] b = new byte[24];
        new SecureRandom().nextBytes(b);
        return HexFormat.of().formatHex(b);
    }
}
