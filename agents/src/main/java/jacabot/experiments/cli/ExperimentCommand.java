package jacabot.experiments.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;
import picocli.CommandLine.Parameters;

/** {@code jacabot experiment NAME}: runs one of the four experiments of the thesis' Chapter 4. */
@Command(name = "experiment", mixinStandardHelpOptions = true,
        description = "Runs an experiment of Chapter 4: obstacle-avoidance, object-picking, navigation, suspend-resume.")
final class ExperimentCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", converter = Experiment.Converter.class,
            completionCandidates = Experiment.Names.class, description = "the experiment: ${COMPLETION-CANDIDATES}")
    private Experiment experiment;

    enum Experiment {
        obstacle_avoidance("1", "obstacle avoidance with the two-sensor MyBot"),
        object_picking("2", "red-cylinder picking with the Khepera"),
        navigation("3", "navigation to the storage point with GPS and compass"),
        suspend_resume("4", "task suspend and resume on a low battery (Appendix B)");

        final String number;
        final String summary;

        Experiment(String number, String summary) {
            this.number = number;
            this.summary = summary;
        }

        @Override
        public String toString() {
            return name().replace('_', '-');
        }

        static final class Converter implements ITypeConverter<Experiment> {
            @Override
            public Experiment convert(String value) {
                for (Experiment e : values()) {
                    if (e.toString().equals(value) || e.number.equals(value)) {
                        return e;
                    }
                }
                throw new TypeConversionException("unknown experiment '" + value + "' (expected one of "
                        + String.join(", ", new Names()) + ")");
            }
        }

        static final class Names extends java.util.ArrayList<String> {
            Names() {
                for (Experiment e : values()) {
                    add(e.toString());
                }
            }
        }
    }

    @Override
    public Integer call() {
        // The agents, middleware and world of the experiments are not built yet: say so honestly.
        System.out.println("Experiment " + experiment.number + " (" + experiment + "): " + experiment.summary + ".");
        System.out.println("Not available yet: this will start the simulated world (worlds/" + experiment
                + ".json), the robot controller, the middleware artifact and the agent (agents/src/main/asl/"
                + experiment + ".asl), and run them until the end of the experiment.");
        return 0;
    }
}
