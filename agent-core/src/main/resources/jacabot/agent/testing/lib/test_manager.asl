// jacabot's AgentSpeak test library: the test manager of a run of `jacabot test`. Each tester
// agent tells it launching_test_set(Me) when it starts and test_results(Me, Passed, Failed, Errors)
// once its tests have run; when every tester has reported it prints the summary lines of Jason
// 3.2's test_manager and stops the system (the runner's own timeout covers a tester that hangs).

+!count_plans(_, _, _).                 // the testers' progress, kept for Jason's protocol

@manager_report[atomic]
+test_results(_, _, _, _)
    :  .count(launching_test_set(_), Started) & .count(test_results(_, _, _, _), Started)
    <- .findall(P, test_results(_, P, _, _), Ps); Passed = math.sum(Ps);
       .findall(F, test_results(_, _, F, _), Fs); Failed = math.sum(Fs);
       .findall(E, test_results(_, _, _, E), Es); Errors = math.sum(Es);
       N = Passed + Failed;
       if (Failed + Errors > 0) {
           .log(severe, "#", N, " tests executed, #", Passed, " passed and #", Failed, " FAILED.");
           if (Errors > 0) { .log(severe, "#", Errors, " test plans ended in an error") };
           .log(severe, "End of Jason unit tests: FAILED!");
       } else {
           .log(info, "#", N, " tests executed, #", Passed, " PASSED and #", Failed, " failed.");
           .log(info, "End of Jason unit tests: PASSED");
       };
       .stopMAS.
+test_results(_, _, _, _).
