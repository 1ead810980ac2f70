package jacabot.agent.runtime;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * A multi-agent system as a {@code .mas2j} file describes it.
 *
 * @param environment the environment class name, or null for Jason's default environment
 */
public record MasProject(String name, String environment, List<String> environmentArgs,
        List<AgentSpec> agents, List<Path> aslSourcePath, Path directory) {

    /** One {@code agents:} entry; {@code instances > 1} makes agents name1..nameN. */
    public record AgentSpec(String name, String file, Map<String, String> options, String archClass,
            String agentClass, int instances) {
    }

    public MasProject {
        environmentArgs = List.copyOf(environmentArgs);
        agents = List.copyOf(agents);
        aslSourcePath = List.copyOf(aslSourcePath);
    }
}
