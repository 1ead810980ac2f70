package jacabot.robot.link;

/**
 * A command frame as read by the controller: a valid command, or one it skipped (an unknown code,
 * a wrong number of arguments, a non-finite argument) with the reason, the stream still in step.
 *
 * @param seq          the middleware's sequence number
 * @param sentMicros   when the middleware sent it ({@link LinkClock})
 * @param receivedMicros when the controller read it
 * @param command      the command, null when skipped
 * @param skipped      why it was skipped, null when valid
 */
public record ReceivedCommand(int seq, long sentMicros, long receivedMicros, Command command, String skipped) {
    public boolean isValid() {
        return command != null;
    }
}
