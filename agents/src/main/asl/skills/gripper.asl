// Skill: where the gripper holds a cylinder (the Khepera model's hold point, 5 cm ahead of the
// robot's centre). Picking includes it; the skills that place a picked or held cylinder read
// gripPoint: search-memory (the places a pick forgets), knocked-aside (a stored cylinder ahead)
// and team-claims (the claim a held cylinder carries).
// Parameters:
gripReach(0.05).     // m ahead of the robot's centre where the gripper holds a cylinder (the model's)
// Reads: location, orientation (the middleware).
gripPoint(Cx, Cz) :- location(X, _, Z) & orientation(O) & gripReach(G) & H = O * math.pi / 180
    & Cx = X + G * math.cos(H) & Cz = Z + G * math.sin(H).
