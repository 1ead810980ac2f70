// Skill test of the initial phase every experiment agent shares (common/initial-phase.asl): when
// no middleware exists yet (lookupArtifact fails) the agent makes one of its experiment's class on
// its port and focuses it. The operations are mocked (agents/README.md "Testing skills").
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/obstacle-avoidance.asl") }

mock_operation(lookupArtifact(_, _), fail("no artifact named middleware", unknown_artifact("middleware"))).
mock_operation(makeArtifact("middleware", _, _, mw), ok).
mock_operation(_, ok).

@[test]
+!test_makes_the_middleware_when_none_exists
    <- !until(mock_called(accept), 3000);
       !assert_true(mock_called(lookupArtifact("middleware", _)));
       ?middlewareClass(C); ?middlewarePort(P);
       !assert_true(mock_called(makeArtifact("middleware", C, [P], mw)));
       !assert_true(mock_called(focus(mw))).
