// A unit test in AgentSpeak, as Jason users write them: `jacabot test examples/asl-tests`.
// The test plans run one after the other, in file order, in one agent (named after the file).
{ include("tester_agent.asl") }

count(0).
+!inc <- ?count(N); -+count(N + 1).

@[test]
+!test_inc_twice <- !inc; !inc; ?count(N); !assert_equals(2, N).

@[test]
+!test_inc_from_ten <- -+count(10); !inc; ?count(N); !assert_greater_than(N, 10); !assert_true(count(11)).
