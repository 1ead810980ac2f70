package jacabot.agent.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.testing.AslTestCase.Status;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jacabot test}'s runner: discovery, one verdict per assertion, errors, mocks, the JUnit report. */
class AslTestRunnerTest {
    private static final String TESTS = """
            { include("tester_agent.asl") }
            b(1).
            mock_operation(battery(480), ok).
            mock_operation(move(_), fail("blocked", obstacle(front))).
            @[test]
            +!test_pass <- X = 1 + 1; !assert_equals(2, X); !assert_true(b(1)); !assert_false(b(2)); !assert_equals([a,b], [b,a]).
            @[test]
            +!test_fail <- !assert_equals(3, 2); !assert_contains([a], c); !assert_between(5, 1, 3).
            @[test]
            +!test_error <- .nth(5, [a], _).
            @[test]
            +!test_mocks <- battery(B); !assert_equals(480, B); !assert_true(mock_called(battery(480)));
                            !try_move; ?moved(R); !assert_equals(obstacle(front), R); !assert_equals(obstacle(back), R).
            +!try_move <- move(1).
            -!try_move[env_failure_reason(R), error_msg(M)] <- +moved(R); !assert_equals("blocked", M).
            @[test]
            +!test_unmocked <- jump.
            """;

    @Test
    void eachAssertionIsATestWithItsVerdict(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("robot_test.asl");
        Files.writeString(file, TESTS);
        var r = new AslTestRunner(null, Duration.ofSeconds(60), 0, null).run(file);
        var lines = r.cases().stream().map(c -> c.test() + " " + c.assertion() + " " + c.status()).toList();
        assertEquals(List.of("test_pass assert_equals PASSED", "test_pass assert_true PASSED", "test_pass assert_false PASSED",
                "test_pass assert_equals PASSED", "test_fail assert_equals FAILED", "test_fail assert_contains FAILED",
                "test_fail assert_between FAILED", "test_error null ERROR", "test_mocks assert_equals PASSED",
                "test_mocks assert_true PASSED", "test_mocks assert_equals PASSED", "test_mocks assert_equals PASSED",
                "test_mocks assert_equals FAILED", "test_unmocked null ERROR"), lines, r.cases().toString());
        assertEquals("assert_equals on event 'test_fail' starting at line 7 FAILED! Expected '3' (number) but had '2' (number)",
                r.cases().get(4).message());
        assertTrue(r.cases().get(7).message().contains("nth: index 5 is out of bounds (1)"), r.cases().get(7).message());
        assertTrue(r.cases().get(13).message().contains("operation jump is not mocked"), r.cases().get(13).message());
        assertEquals("#12 tests executed, #8 passed and #4 FAILED.", r.managerSummary());
        assertEquals(8, r.passed());
        assertEquals(6, r.failed()); // 4 failed assertions (the manager's count) and 2 errors
        Path xml = JUnitXmlReport.write(dir.resolve("junit"), "robot_test", r);
        String report = Files.readString(xml);
        assertTrue(report.contains("<testsuite name=\"robot_test\" tests=\"14\" failures=\"4\" errors=\"2\""), report);
    }

    @Test
    void discoveryTakesTestFilesAndTestProjectsOnly(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("a_test.asl"), "{ include(\"tester_agent.asl\") }\n@[test]\n+!test_a <- !force_pass.\n");
        Files.writeString(dir.resolve("helper.asl"), "+!h.\n");
        Files.createDirectories(dir.resolve("proj/asl"));
        Files.writeString(dir.resolve("proj/unit.mas2j"), "MAS u { agents: test_manager manager.asl; t; aslSourcePath: \"asl\"; }\n");
        Files.writeString(dir.resolve("proj/asl/t.asl"), "{ include(\"tester_agent.asl\") }\n@[test]\n+!test_t <- !force_pass.\n");
        Files.writeString(dir.resolve("proj/asl/manager.asl"), "{ include(\"test_manager.asl\") }\n");
        Files.createDirectories(dir.resolve("other"));
        Files.writeString(dir.resolve("other/plain.mas2j"), "MAS p { agents: x; }\n");
        assertEquals(List.of(dir.resolve("a_test.asl"), dir.resolve("proj/unit.mas2j")), AslTestRunner.discover(List.of(dir)));
        // a project without copies of the library: its includes read the library's
        var r = new AslTestRunner(null, Duration.ofSeconds(60), 0, null).run(dir.resolve("proj/unit.mas2j"));
        assertEquals(List.of(new AslTestCase("t", "test_t", "force_pass", Status.PASSED, "")), r.cases());
    }

    @Test
    void simulatedTimeLetsTheAgentFinishBeforeAWaitEnds(@TempDir Path dir) throws Exception {
        String busy = """
                { include("tester_agent.asl") }
                @[test]
                +!test_busy <- !!count(20000); .wait(1); !assert_true(done).
                +!count(0) <- +done.
                +!count(N) <- !!count(N - 1).
                """;
        // 20000 reasoning cycles take far longer than 1 ms on the wall clock
        var wall = new AslTestRunner(null, Duration.ofSeconds(60), 0, null).run(Files.writeString(dir.resolve("busy_test.asl"), busy));
        assertEquals(Status.FAILED, wall.cases().get(0).status(), wall.cases().toString());
        // and a minute of simulated time is no real time at all
        Path file = Files.writeString(dir.resolve("busy_clock_test.asl"), busy + """
                @[test]
                +!test_clock <- .system_time(T0); .wait(60000); .system_time(T1); !assert_equals(60000, T1 - T0).
                """);
        var simulated = new AslTestRunner(null, Duration.ofSeconds(60), 0, null, true).run(file);
        assertEquals(List.of(Status.PASSED, Status.PASSED), simulated.cases().stream().map(AslTestCase::status).toList());
        assertTrue(simulated.millis() < 5000, simulated.millis() + " ms");
    }

    @Test
    void simulatedTimeEndsARunThatCannotGoOnAtOnce(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("stuck_test.asl"), """
                { include("tester_agent.asl") }
                @[test]
                +!test_stuck <- .wait({+never}); !force_pass.
                """);
        var r = new AslTestRunner(null, Duration.ofSeconds(60), 0, null, true).run(file);
        assertEquals(Status.ERROR, r.cases().get(r.cases().size() - 1).status());
        assertTrue(r.cases().get(r.cases().size() - 1).message().contains("nothing more could happen"), r.cases().toString());
        assertTrue(r.millis() < 5000, r.millis() + " ms");
    }
}
