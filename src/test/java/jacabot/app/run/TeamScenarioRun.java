package jacabot.app.run;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.cartago.CartagoException;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;

/** The team-delivery agents on a world a scenario test writes out: quiet, and without step logs. */
final class TeamScenarioRun {
    private TeamScenarioRun() {
    }

    /** {@return the world of {@code json}, read as the file {@code name} (named in its errors)} */
    static SimWorld world(String json, String name) throws WorldFileException {
        return SimWorld.of(WorldFileReader.parse(json, name));
    }

    /** {@return a run of the team-delivery agents on {@code world}, printing nothing} */
    static TeamLockstepRun quiet(SimWorld world, long seed) throws AslSyntaxException, CartagoException {
        var run = new TeamLockstepRun(world, TeamTwoProcessTest.AGENT, seed, new PrintStream(OutputStream.nullOutputStream()));
        run.stepLogs(false);
        return run;
    }
}
