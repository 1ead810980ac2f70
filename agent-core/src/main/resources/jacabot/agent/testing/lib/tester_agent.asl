// jacabot's AgentSpeak test library: the tester agent. A test file includes it
// ({ include("tester_agent.asl") }, or Jason's "$jasonJar/test/jason/inc/tester_agent.asl") and
// labels its test plans [test]: each runs in turn, in file order, once the agent starts.
// The goal names and console lines are those of Jason 3.2's tester agent, which its users know;
// the code is jacabot's. A test plan that fails outside an assertion is reported as an error
// (with its error_msg) and the next test runs (Jason's tester stops the whole run there).

{ include("test_assert.asl") }

!execute_test_plans.

@tester_run_all
+!execute_test_plans : .my_name(Me)
    <- .send(test_manager, tell, launching_test_set(Me));
       .relevant_plans({+!_}, Plans, Labels);
       for (.member(Label[test], Labels)) {
           .findall(G, .member({@L +!G : _ <- _}, Plans) & Label = L, [Goal|_]);
           !execute_test_plan(Goal);
       }
       .count(test(_, _, passed, _), Passed);
       .count(test(_, _, failed, _), Failed);
       .count(test_error(_, _), Errors);
       .send(test_manager, tell, test_results(Me, Passed, Failed, Errors));
       .send(test_manager, tell, launched_test_set(Me)).

// the test about to run (running_test(Goal), for the assertions' messages)
@tester_run_one
+!execute_test_plan(Goal)
    <- -+running_test(Goal);
       .send(test_manager, achieve, count_plans(launched, Goal, _));
       !Goal;
       .send(test_manager, achieve, count_plans(achieved, Goal, _)).
-!execute_test_plan(Goal)[error(E), error_msg(M), code(C), code_src(S), code_line(L)]
    <- +test_error(Goal, M);
       .log(severe, "Error '", E, "' in '", S, "' on event '", Goal, "' at line ", L, " FAILED! Message: '", M, "' (", C, ")");
       .send(test_manager, achieve, count_plans(achieved, Goal, _)).
-!execute_test_plan(Goal)[error(E), error_msg(M)]
    <- +test_error(Goal, M);
       .log(severe, "Error '", E, "' on event '", Goal, "' FAILED! Message: '", M);
       .send(test_manager, achieve, count_plans(achieved, Goal, _)).
