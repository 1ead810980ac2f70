package jacabot.agent.testing;

/**
 * One test of an AgentSpeak test run, as Jason's test_manager counts them: one assertion checked
 * ({@code PASSED} or {@code FAILED}, with the assertion's message), or a test plan that ended in
 * an error ({@code ERROR}, with the failure's {@code error_msg}), or a run that could not finish.
 *
 * @param agent     the tester agent
 * @param test      the test goal ({@code test_abolish}), or {@code "(run)"} for the run itself
 * @param assertion {@code assert_equals}, ..., or null for an error
 */
public record AslTestCase(String agent, String test, String assertion, Status status, String message) {
    public enum Status { PASSED, FAILED, ERROR }

    public boolean passed() {
        return status == Status.PASSED;
    }
}
