package jacabot.experiments.link;

import jacabot.robot.link.Uplink;

/** What a {@link RobotConnection} tells its link ({@link ControllerSession}). */
interface ConnectionOwner {
    /** The handshake succeeded: this connection is the robot now. */
    void attached(RobotConnection c);

    void frame(RobotConnection c, Uplink frame);

    /** A frame was dropped (malformed, or the link failed on it). */
    void badFrame(RobotConnection c, String reason);

    /** The handshake failed: the connection never became the robot's. */
    void refused(RobotConnection c, String reason, boolean authentication);

    /** The connection ended (reason for the log and {@code Disconnected}). */
    void detached(RobotConnection c, String reason);
}
