// Skill: a way out of the storage corner, not in the thesis. After the put-down the robot turns
// back and drives out blind (delivery: no distance sensing in the area, no progress ignored there);
// one that came in at a slant, or was pushed on its way in, faced a wall of the corner and drove
// into it until its battery ran low (team world 2, four robots: 220 s; suspend/resume, wide world
// 268, seed 1: 480 s against the wall, every low battery left for after the delivery,
// @rechargeOutOfArea, until the battery was empty). No progress there after the put-down: it turns
// to the arena's centre, away from the walls, and drives on out.
// Reads: insideArea, delivering, picking (delivery, picking); waitingStorage (team-storage's, when
// included: a robot waiting its turn stands still); location; the middleware's stuck.
// Needs: delivery (heading's !balance, desired). Include it before delivery (its @stuckIgnored
// comes after), in a team right after team-storage.

@stuckLeavingStorage
+stuck : insideArea & not delivering & not picking & not waitingStorage & location(X, _, Z)
    <- println("No progress leaving the storage area: out towards the arena's centre");
       computeAngle(X, Z, 0, 0, A); -+desired(A); !balance; forward.
