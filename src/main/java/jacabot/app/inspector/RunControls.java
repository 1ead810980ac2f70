package jacabot.app.inspector;

import static jacabot.app.inspector.Replies.body;
import static jacabot.app.inspector.Replies.query;
import static jacabot.app.inspector.Replies.sendJson;
import static jacabot.app.inspector.Replies.sendText;
import static jacabot.app.inspector.Replies.time;

import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executor;

/**
 * The inspector page's hold on the run: the {@link Debugger}'s controls ({@code /api/debug}) and,
 * when the run allows it ({@link RunEdits}), what-ifs ({@code /api/whatif}) and plan reloads
 * ({@code /api/reload}). The rest of the page only reads.
 */
final class RunControls {
    private final Executor threads;
    volatile Debugger debugger;
    volatile RunEdits edits;
    final List<WhatIfJob> whatIfs = new CopyOnWriteArrayList<>();

    /** @param threads where what-ifs run (the inspector's own) */
    RunControls(Executor threads) {
        this.threads = threads;
    }

    /** {@return the run's own program text for the page's editor ("" when the run cannot be edited)} */
    String source() {
        RunEdits e = edits;
        return e == null ? "" : e.source();
    }

    /** The debugger's state: where the run is halted (or null) and the breakpoints. */
    Map<String, Object> debugState() {
        Debugger d = debugger;
        var out = new LinkedHashMap<String, Object>();
        out.put("available", d != null);
        Debugger.State s = d == null ? null : d.state();
        // the page shows no state older than the one it shows (a command's answer may come after a push)
        out.put("version", s == null ? 0 : s.version());
        Debugger.Halt h = s == null ? null : s.halted();
        out.put("halted", h == null ? null : Map.of("timeMs", h.timeMs(), "reason", h.reason(), "mind", h.mind()));
        out.put("breakpoints", s == null ? List.of() : s.breakpoints());
        RunEdits e = edits;
        out.put("editable", e != null);
        out.put("reload", e == null ? RunEdits.Reload.NONE : e.reloads());
        out.put("whatIfRefusal", e == null ? null : e.whatIfRefusal());
        out.put("whatIfs", List.copyOf(whatIfs));
        return out;
    }

    /** {@code GET /api/debug}: the state; {@code POST /api/debug?cmd=continue|step|pause|break|delete[&spec=S]}: a command. */
    void debug(HttpExchange ex) throws IOException {
        Debugger d = debugger;
        if (ex.getRequestMethod().equals("POST")) {
            if (d == null) {
                sendText(ex, 409, "this run cannot halt (lockstep runs only)");
                return;
            }
            String cmd = query(ex).getOrDefault("cmd", ""), spec = query(ex).getOrDefault("spec", "");
            try {
                switch (cmd) {
                    case "continue" -> d.resume();
                    case "step" -> d.step();
                    case "cycle" -> d.stepCycle();
                    case "pause" -> d.pause();
                    case "break" -> d.add(spec);
                    case "delete" -> d.remove(spec);
                    default -> throw new IllegalArgumentException("unknown command '" + cmd + "'");
                }
            } catch (IllegalArgumentException e) {
                sendText(ex, 400, e.getMessage());
                return;
            }
        }
        sendJson(ex, debugState());
    }

    /**
     * {@code POST /api/whatif?t=MS&seconds=S} with the edited program as the body: starts a
     * what-if on a thread of its own; its history appears as another agent once it has run.
     */
    void whatIf(HttpExchange ex) throws IOException {
        if (!ex.getRequestMethod().equals("POST")) {
            sendJson(ex, List.copyOf(whatIfs));
            return;
        }
        RunEdits e = edits;
        if (e == null) {
            sendText(ex, 409, "this run has no step log to start a what-if from");
            return;
        }
        if (e.whatIfRefusal() != null) {
            sendText(ex, 409, e.whatIfRefusal());
            return;
        }
        long at = time(query(ex).get("t")), seconds = time(query(ex).get("seconds"));
        if (at < 0 || seconds <= 0) {
            sendText(ex, 400, "a what-if needs t (ms, at least 0) and seconds (more than 0)");
            return;
        }
        String program = body(ex);
        var job = new WhatIfJob("what-if " + (whatIfs.size() + 1) + " from " + at / 1000.0 + " s", at, seconds);
        whatIfs.add(job);
        threads.execute(() -> {
            try {
                e.whatIf(job, program);
            } catch (IllegalArgumentException x) {
                job.failed(x.getMessage());
            } catch (Exception x) {
                job.failed(x.toString());
            }
        });
        sendJson(ex, job);
    }

    /**
     * {@code POST /api/reload} with a program as the body: its plans replace the live run's (a
     * lockstep run's at its halt, a real-time run's at the agent's next cycle); the answer says what happened.
     */
    void reload(HttpExchange ex) throws IOException {
        RunEdits e = edits;
        if (!ex.getRequestMethod().equals("POST") || e == null) {
            sendText(ex, 409, "POST a program to a live run's inspector");
            return;
        }
        try {
            String what = e.reload(body(ex));
            sendJson(ex, Map.of("message", what, "debug", debugState()));
        } catch (IllegalStateException | IllegalArgumentException x) {
            sendText(ex, 409, x.getMessage());
        } catch (Exception x) {
            sendText(ex, 500, x.toString());
        }
    }
}
