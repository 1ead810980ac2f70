package jacabot.cartago.bridge;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * A JaCaMo project ({@code .jcm}) as far as jacabot runs it: agents, workspaces with their
 * artifacts, and the class and source paths.
 */
public record JcmProject(Path file, String name, List<AgentDecl> agents, List<WorkspaceDecl> workspaces,
        List<String> classPath, List<String> aslPath) {

    /**
     * {@code agent NAME [: SOURCE] { beliefs: ..., goals: ..., focus: w.a, join: w, instances: N, ag-arch: C }}.
     *
     * @param beliefs the text after {@code beliefs:} (AgentSpeak literals separated by commas), or null
     * @param focus   {@code workspace.artifact} names
     * @param focusAt {@code file:line:col} of each {@code focus} entry
     * @param optionsAt {@code file:line:col} of the {@code beliefs} and {@code goals} entries, by key (the first of each)
     */
    public record AgentDecl(String name, String source, String beliefs, String goals, List<String> focus,
            List<String> focusAt, List<String> join, int instances, String archClass, Map<String, String> optionsAt) {
    }

    /** {@code workspace NAME { artifact A: C(args) ... agents: a, b }}. */
    public record WorkspaceDecl(String name, List<ArtifactDecl> artifacts, List<String> agents) {
    }

    /**
     * {@code artifact NAME: CLASS(ARGS)}.
     *
     * @param args the text between the parentheses (AgentSpeak terms), or "" for none
     * @param where {@code file:line:col} of the declaration
     */
    public record ArtifactDecl(String name, String className, String args, String where) {
    }
}
