package jacabot.robot.link;

import java.io.IOException;

/** The other side broke the protocol (garbage, a foreign class, a truncated frame): close the connection. */
public final class ProtocolException extends IOException {
    private static final long serialVersionUID = 1L;

    public ProtocolException(String message) {
        super(message);
    }

    public ProtocolException(String message, Throwable cause) {
        super(message, cause);
    }
}
