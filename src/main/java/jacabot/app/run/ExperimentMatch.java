package jacabot.app.run;

import jacabot.robot.Experiment;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * Whether a world, an agent and a middleware were made for the same experiment. Each experiment's
 * agent expects its own middleware's observable properties and its own landmarks; a mix-up runs,
 * but the robot then does nothing sensible, so it is worth one warning before the run.
 */
public final class ExperimentMatch {
    private static final Pattern MIDDLEWARE = Pattern.compile("jacabot\\.experiments\\.(\\w+Middleware)\\b");

    private ExperimentMatch() {
    }

    /** {@return the experiment whose world files are named like {@code name} (navigation, navigation-gen-7, ...)} */
    public static Optional<Experiment> ofWorld(String name) {
        Experiment best = null;
        for (Experiment e : Experiment.values()) {
            if (name.equals(e.id()) || name.startsWith(e.id() + "-") || name.startsWith(e.id() + "_")) {
                best = e;
            }
        }
        return Optional.ofNullable(best);
    }

    /** {@return the experiment whose middleware the class is, by its simple name} */
    public static Optional<Experiment> ofMiddleware(String simpleName) {
        for (Experiment e : Experiment.values()) {
            if (Middlewares.of(e).getSimpleName().equals(simpleName)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /** {@return the middleware classes an agent's text makes (its makeArtifact lines), by simple name} */
    public static List<String> middlewaresMadeBy(String agentSource) {
        var names = new ArrayList<String>();
        var m = MIDDLEWARE.matcher(agentSource);
        while (m.find()) {
            if (!names.contains(m.group(1))) {
                names.add(m.group(1));
            }
        }
        return names;
    }

    /**
     * {@return the warnings for running {@code experiment} on a world named {@code worldName} (from
     * {@code worldFile}) with the agent {@code agentSource} (from {@code agentFile})}
     */
    public static List<String> check(Experiment experiment, String worldName, String worldFile, String agentSource,
            String agentFile) {
        var warnings = new ArrayList<String>();
        ofWorld(worldName).filter(w -> w != experiment).ifPresent(w -> warnings.add(worldFile + " is a world of experiment "
                + w.number() + " (" + w + "), not of " + experiment + "; its landmarks and robot may not suit this agent "
                + "(jacabot experiment " + w + " runs it)"));
        String own = Middlewares.of(experiment).getSimpleName();
        for (String made : middlewaresMadeBy(agentSource)) {
            // by the class, not the experiment: tidy-up's agent makes the SuspendResumeMiddleware, its own too
            ofMiddleware(made).filter(a -> !made.equals(own)).ifPresent(a -> warnings.add(agentFile + " is written for "
                    + "experiment " + a.number() + " (" + a + ": it makes the " + made + "), but runs here with the "
                    + Middlewares.of(experiment).getSimpleName() + " of " + experiment
                    + "; its percepts and actions may not match"));
        }
        return warnings;
    }

    /**
     * {@return warnings for a Jason project named {@code masName} whose agents make the given
     * middlewares}: the project of experiment 3 should make experiment 3's middleware
     */
    public static List<String> checkProject(String masName, String projectFile, List<String> middlewares) {
        var warnings = new ArrayList<String>();
        Optional<Experiment> project = Experiment.parse(masName.replace('_', '-'));
        for (String made : middlewares) {
            var of = ofMiddleware(made);
            if (project.isPresent() && of.isPresent() && !made.equals(Middlewares.of(project.get()).getSimpleName())) {
                warnings.add(projectFile + ": the project '" + masName + "' makes the " + made + " of experiment "
                        + of.get().number() + " (" + of.get() + "); its controller must then run a world of " + of.get()
                        + " (jacabot controller --world worlds/" + of.get().id() + ".json)");
            }
        }
        return warnings;
    }
}
