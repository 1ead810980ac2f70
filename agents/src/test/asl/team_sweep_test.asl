// Skill tests of the team's share of the sweep (skills/team-sweep.asl, in team-delivery.asl): a
// robot of a team starts its sweep at its own share of the lanes, by its rank among the teammates
// on the board; a robot alone starts where one robot does. Run: jacabot test agents/src/test/asl
{ include("tester_agent.asl") }
{ include("skill_test_support.asl") }
{ include("../../main/asl/team-delivery.asl") }

arena(2, 2).
storagePoint(0.75, 0.75).
storageRadius(0.06).
charger(-0.75, 0.75).

mock_operation(lookupArtifact(_, middleware), ok).
mock_operation(computeAngle(_, _, _, _, 45), ok).
mock_operation(_, ok).

@[test]
+!test_a_robot_alone_starts_at_the_first_lane
    <- +robotAt(team_sweep_test, 0, 0);
       !planSweep;
       !assert_true(waypoint(-0.75, -0.75, _)).                  // the first lane's start, as one robot

@[test]
+!test_a_robot_of_four_starts_at_its_share_of_the_lanes
    <- .abolish(sweep(_)); .abolish(waypoint(_, _, _)); -sweepShared;
       +robotAt(khepera1, 0.5, 0); +robotAt(khepera2, 0, 0.5); +robotAt(khepera3, -0.5, 0);
       !planSweep;                                               // 7 waypoints (one in the storage area left out)
       !assert_true(waypoint(-0.75, 0.25, _));                   // the last of 4 by name: the third lane
       !assert_true(sweep([[0.75, 0.25], [-0.75, 0.75], [-0.75, -0.75], [0.75, -0.75], [0.75, -0.25],
                           [-0.75, -0.25], [-0.75, 0.25]]));     // then the lanes after it, and round
       !planSweep;                                               // the next search goes on from there
       !assert_true(waypoint(0.75, 0.25, _)).
