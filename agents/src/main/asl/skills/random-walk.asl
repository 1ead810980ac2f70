// Skill: random motion (thesis Chapter 4 §5, the common aspects; §1.1 gives its strategy): forward for a random time, or a turn left or right
// for a random time and a second forward. The last +!move plans: every other skill's come first.
// Reads: legSpeed(V) (optional): the wheel speed of the straight stretches; without it, the
// thesis' forward.

@walkStraight +!move(N) : N <= 0.5 <- !goStraight; .random(R); W = R * 10000; .wait(W).
@walkLeft +!move(N) : N <= 0.75 & N > 0.5 <- turnLeft; .random(R); W = R * 10000 / 2; .wait(W); !goStraight; .wait(1000).
@walkRight +!move(N) : N < 1 & N > 0.75 <- turnRight; .random(R); W = R * 10000 / 2; .wait(W); !goStraight; .wait(1000).

@straightAtLegSpeed +!goStraight : legSpeed(V) <- setSpeeds(V, V).
@straightForward +!goStraight <- forward.
