package jacabot.robot.link;

import java.io.IOException;

/** The peer could not prove it holds the link's {@link LinkSecret}: close, and count the attempt. */
public final class AuthenticationException extends IOException {
    private static final long serialVersionUID = 1L;

    public AuthenticationException(String message) {
        super(message);
    }
}
