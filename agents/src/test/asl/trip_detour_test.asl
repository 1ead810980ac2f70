// Skill test of the recharge trip's detour (skills/recharge-trip.asl's @realignAfterDetour, with an
// agent's detourFirst): on the trip, a detour's drive on is not cut short by the steering's
// re-alignment; on a delivery, or without detourFirst, the re-alignment turns the robot at once.
// The operations are mocked (agents/README.md "Testing skills").
// a detour that only drives on (heading's @detour avoids first): before the includes, so it is taken first
@testDetour +!detour(_) : testDetour <- .wait(3000).
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/skills/recharge-trip.asl") }
{ include("../../main/asl/skills/heading.asl") }

maxSpeed(100).
location(0, 0, 0).
orientation(0).
charger(-0.4, 0.4).
targetPoint(-0.4, 0.4).
aim(-0.2, -0.1).
desired(300).
travelling :- delivering.
mock_operation(_, ok).

@[test]
+!test_on_the_trip_a_detours_drive_is_not_cut_short_by_the_steerings_realignment
    <- +detourFirst; +charging; +testDetour; !!detour(1); .wait(50);
       !forget_calls; !realign; .wait(100);
       !assert_false(mock_called(setSpeeds(_, _)));
       .drop_intention(detour(_)); -charging; -testDetour; -detourFirst.

@[test]
+!test_on_a_delivery_the_realignment_turns_at_once
    <- +detourFirst; +delivering; +testDetour; !!detour(1); .wait(50);
       !forget_calls; !realign; .wait(100);
       !assert_true(mock_called(setSpeeds(_, _)));
       .drop_intention(balance); .drop_intention(detour(_)); -delivering; -testDetour; -detourFirst; stop.

@[test]
+!test_without_detour_first_the_realignment_turns_at_once
    <- +charging; +testDetour; !!detour(1); .wait(50);
       !forget_calls; !realign; .wait(100);
       !assert_true(mock_called(setSpeeds(_, _)));
       .drop_intention(balance); .drop_intention(detour(_)); -charging; -testDetour; stop.
