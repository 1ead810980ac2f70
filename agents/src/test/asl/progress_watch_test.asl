// Skill test of the progress watch (skills/progress-watch.asl): its set-up goal gives the
// middleware the two windows of its stuckWindows belief. The operations are mocked
// (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/progress-watch.asl") }

mock_operation(_, ok).

@[test]
+!test_set_up_gives_the_default_windows
    <- !forget_calls; ?setUpGoal(G); !G;
       !assert_equals(setUpProgressWatch, G);
       !assert_true(mock_called(progressWindows(14000, 0.03, 40000, 0.12))).

@[test]
+!test_set_up_gives_the_agents_own_windows
    <- !forget_calls; -+stuckWindows(5000, 0.05, 20000, 0.2); !setUpProgressWatch;
       !assert_true(mock_called(progressWindows(5000, 0.05, 20000, 0.2)));
       !assert_false(mock_called(progressWindows(14000, _, _, _))).
