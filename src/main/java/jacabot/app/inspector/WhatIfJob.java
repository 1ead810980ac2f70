package jacabot.app.inspector;

/**
 * A what-if started from the page: from which instant, how long, and how it went: running, done
 * (with the time the plans were swapped and the first step where it differs from the run it
 * came from) or failed (why). Written by its run's thread, read by the page's (JSON getters).
 */
public final class WhatIfJob {
    private final String name;
    private final long atMs;
    private final long seconds;
    private volatile String state = "running";
    private volatile String message = "";
    private volatile long swappedAtMs = -1;
    private volatile long divergesAtMs = -1;
    private volatile String folder = "";

    public WhatIfJob(String name, long atMs, long seconds) {
        this.name = name;
        this.atMs = atMs;
        this.seconds = seconds;
    }

    /** {@return its name: the agent the page shows its history as} */
    public String getName() {
        return name;
    }

    public long getAtMs() {
        return atMs;
    }

    public long getSeconds() {
        return seconds;
    }

    /** {@return running, done or failed} */
    public String getState() {
        return state;
    }

    public String getMessage() {
        return message;
    }

    public long getSwappedAtMs() {
        return swappedAtMs;
    }

    /** {@return the time of the first step that differs from the original run (-1: none differs)} */
    public long getDivergesAtMs() {
        return divergesAtMs;
    }

    /** {@return where its step log went} */
    public String getFolder() {
        return folder;
    }

    /** It ran: where it wrote, when the plans were swapped, where it first differs. */
    public void done(String where, long swapped, long diverges) {
        folder = where;
        swappedAtMs = swapped;
        divergesAtMs = diverges;
        message = swapped < 0 ? "the run ended before the instant: the plans were never swapped" : "";
        state = "done";
    }

    public void failed(String why) {
        message = why;
        state = "failed";
    }
}
