package jacabot.cartago.bridge;

import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.Clock;
import jacabot.agent.runtime.LocalMAS;
import jacabot.cartago.SimulatedClock;
import jacabot.cartago.bridge.CAgentArch;
import jacabot.cartago.bridge.CartagoEnvironment;
import jacabot.cartago.Workspace;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.stream.Collectors;

/** A JaCa system of inline agents in one stepped workspace, run deterministically. */
final class JacaHarness {
    final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    final PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
    final LocalMAS mas = new LocalMAS(Clock.wall(), out, 7);
    final Workspace workspace;
    final JacaStepper stepper;

    final SimulatedClock clock = new SimulatedClock();

    JacaHarness() {
        workspace = Workspace.builder("main").stepped().clock(clock).console(out).build();
        mas.setEnvironment(new CartagoEnvironment(workspace), List.of());
        stepper = new JacaStepper(mas, workspace);
    }

    JacaHarness agent(String name, String source) throws Exception {
        var parser = new AslParser();
        mas.createAgent(name, parser.parse(source, name + ".asl"), parser, CAgentArch::new);
        return this;
    }

    JacaHarness run(long cycles) {
        stepper.runUntilQuiescent(cycles);
        return this;
    }

    List<String> lines() {
        return bytes.toString(StandardCharsets.UTF_8).lines().collect(Collectors.toList());
    }
}
