package jacabot.agent.testing;

import jacabot.agent.testing.AslTestCase.Status;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the console of an AgentSpeak test run: the lines that Jason 3.2's test library (and
 * jacabot's, which prints the same) writes for each assertion, error and summary, from
 * {@code [agent] text} lines. Any other line is the program's own and is ignored.
 */
final class TestConsoleParser {
    private static final Pattern AGENT_LINE = Pattern.compile("^\\[([^\\]]+)\\] ?(.*)$");
    private static final Pattern PASSED = Pattern.compile("^(\\w+) on event '(.*)' PASSED$");
    private static final Pattern FAILED = Pattern.compile("^(\\w+) on event '(.*)' starting at line (\\d+) FAILED! ?(.*)$");
    private static final Pattern FORCED = Pattern.compile("^force_failure on event '(.*)' forcedly FAILED! Msg: '(.*)'$");
    private static final Pattern NOT_PERFORMED = Pattern.compile("^(\\w+) (.*) could not be performed.*FAILED!$");
    private static final Pattern ERROR = Pattern.compile("^Error '(.*?)' in '(.*?)' on event '(.*?)' at line (\\d+) FAILED! Message: '(.*)$");
    private static final Pattern ERROR_SHORT = Pattern.compile("^Error '(.*?)' on event '(.*?)' FAILED! Message: '(.*)$");
    private static final Pattern NOT_ACHIEVED = Pattern.compile("^Test '(.*)' was NOT ACHIEVED, agent '(.*)' has FAILED on testing!$");
    private static final Pattern SUMMARY = Pattern.compile("^#(\\d+) tests executed, #(\\d+) (?:PASSED|passed) and #(\\d+) (?:failed|FAILED)\\.$");

    final List<AslTestCase> cases = new ArrayList<>();
    /** The manager's "#N tests executed, #P passed and #F failed." line, or null. */
    String summary;
    int summaryExecuted = -1;
    int summaryPassed = -1;
    boolean fatal;

    synchronized void line(String line) {
        Matcher a = AGENT_LINE.matcher(line);
        if (!a.matches()) {
            return;
        }
        String agent = a.group(1);
        String text = a.group(2);
        Matcher m;
        if ((m = PASSED.matcher(text)).matches()) {
            cases.add(new AslTestCase(agent, m.group(2), m.group(1), Status.PASSED, ""));
        } else if ((m = FAILED.matcher(text)).matches()) {
            cases.add(new AslTestCase(agent, m.group(2), m.group(1), Status.FAILED, text));
        } else if ((m = FORCED.matcher(text)).matches()) {
            cases.add(new AslTestCase(agent, m.group(1), "force_failure", Status.FAILED, text));
        } else if ((m = NOT_PERFORMED.matcher(text)).matches()) {
            cases.add(new AslTestCase(agent, "?", m.group(1), Status.FAILED, text));
        } else if ((m = ERROR.matcher(text)).matches()) {
            cases.add(new AslTestCase(agent, m.group(3), null, Status.ERROR,
                    "error " + m.group(1) + " at " + m.group(2) + ":" + m.group(4) + ": " + m.group(5)));
        } else if ((m = ERROR_SHORT.matcher(text)).matches()) {
            cases.add(new AslTestCase(agent, m.group(2), null, Status.ERROR, "error " + m.group(1) + ": " + m.group(3)));
        } else if ((m = NOT_ACHIEVED.matcher(text)).matches()) {
            cases.add(new AslTestCase(m.group(2), m.group(1), null, Status.ERROR, "the test plan was not achieved"));
        } else if ((m = SUMMARY.matcher(text)).matches()) {
            summary = text;
            summaryExecuted = Integer.parseInt(m.group(1));
            summaryPassed = Integer.parseInt(m.group(2));
        } else if (text.startsWith("Fatal error informed")) {
            fatal = true;
        }
    }

    synchronized List<AslTestCase> cases() {
        return List.copyOf(cases);
    }
}
