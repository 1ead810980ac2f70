package jacabot.robot.link;

import java.net.SocketAddress;

/**
 * The middleware's turn of a lockstep step, taken on the controller's simulation thread when both
 * ends live in one process and talk over TCP: right after writing a step, the simulation thread
 * lets the middleware read it from its end of the socket and answer it (the agent reasons there),
 * then reads the answer from its own end. The bytes go the socket's way as before (handshake,
 * frames, codecs); what goes is the two thread wake-ups of every step, on this machine kind each
 * about as long as a step's own work ({@code docs/performance.md}).
 *
 * <p>Two processes keep a reading thread at each end ({@link LockstepSpin}): there the other end
 * cannot be run on this thread.
 */
public interface LockstepTurn {
    /**
     * Step {@code step} has just been written on the connection whose controller end is
     * {@code controller}: the middleware reads it and answers it on this thread.
     *
     * @return false when it could not (no such connection is lent to turns, or turns were released):
     *     the middleware's own thread then reads and answers, as between two processes
     */
    boolean take(SocketAddress controller, long step);

    /** No more turns: the middleware reads on its own thread again (what is left: the controller's goodbye). */
    void release();
}
