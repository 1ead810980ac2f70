package jacabot.app.inspector;

import java.io.IOException;
import java.util.List;
import java.util.function.Consumer;

/**
 * An agent's whole past on disk (the run's step log), read on demand, so that the inspector's
 * time slider reaches the run's start while the heap holds only the recent frames.
 */
public interface MindArchive {
    /** {@return the time of the first instant on disk, or -1 before any} */
    long firstTimeMs();

    /** {@return the time of the last instant on disk, or -1 before any} */
    long lastTimeMs();

    /** {@return the frame at the last instant at or before {@code timeMs} (the first one when before it); null when empty} */
    MindHistory.Frame at(long timeMs) throws IOException;

    /** {@return up to {@code max} plan selections at or before {@code timeMs}, oldest first} */
    List<MindState.Selection> selectionsUpTo(long timeMs, int max) throws IOException;

    /** Hands every step's mind, from the first to the last on disk, to {@code each} (the time views) */
    void forEachMind(Consumer<MindState> each) throws IOException;
}
