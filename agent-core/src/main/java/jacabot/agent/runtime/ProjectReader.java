package jacabot.agent.runtime;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.SourceResolver;
import jacabot.agent.syntax.AgentProgram;
import java.nio.file.Path;
import java.util.ServiceLoader;

/**
 * Reads a project format other than {@code .mas2j} (found with {@link ServiceLoader}: e.g. the
 * JaCa bridge's JaCaMo {@code .jcm}). The launcher asks it for the project, lets it adapt each
 * agent's program, and lets it prepare the environment before the agents are made. One instance
 * reads one file.
 */
public interface ProjectReader {
    /** {@return whether this reader reads {@code file} (by its extension)} */
    boolean reads(Path file);

    /** Reads the project; a mistake in it is a {@link MasLauncher.UserError} naming {@code file:line:col}. */
    MasProject read(Path file) throws MasLauncher.UserError;

    /** {@return where the agents' included sources come from, given the launcher's resolver} */
    default SourceResolver includes(SourceResolver files) {
        return files;
    }

    /** Called once the environment is set, before any agent is made. */
    default void prepare(LocalMAS mas) throws MasLauncher.UserError {
    }

    /** {@return an agent's program as the project makes it (more plans, goals)} */
    default AgentProgram adapt(MasProject.AgentSpec spec, AgentProgram program, AslParser parser) throws MasLauncher.UserError {
        return program;
    }

    /**
     * {@return {@code file:line:col} of an agent's option ({@code beliefs}, {@code goals}) in the
     * project, when the reader knows it; null: the launcher names the project file alone}
     */
    default String optionPlace(MasProject.AgentSpec spec, String option) {
        return null;
    }

    /** {@return a new reader for {@code file}, or null when no reader on the class path reads it} */
    static ProjectReader forFile(Path file) {
        for (ProjectReader r : ServiceLoader.load(ProjectReader.class)) {
            if (r.reads(file)) {
                return r;
            }
        }
        return null;
    }
}
