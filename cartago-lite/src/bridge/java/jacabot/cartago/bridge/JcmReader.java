package jacabot.cartago.bridge;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.parser.SourceResolver;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.MasLauncher.UserError;
import jacabot.agent.runtime.MasProject;
import jacabot.agent.runtime.ProjectReader;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.cartago.CartagoException;
import jacabot.cartago.Workspace;
import jacabot.cartago.bridge.JcmProject.AgentDecl;
import jacabot.cartago.bridge.JcmProject.ArtifactDecl;
import jacabot.cartago.bridge.JcmProject.WorkspaceDecl;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * {@code jacabot run project.jcm}: a JaCaMo project as a JaCa system. The agents run with
 * {@link CartagoEnvironment} and the JaCa architecture; the workspaces and their artifacts are
 * made before the agents start; an agent's {@code join:} and {@code focus:} (and a workspace's
 * {@code agents:}) are done by an atomic first goal, {@code jcm_setup}, before its own goals run.
 * JaCaMo's template includes ({@code $jacamoJar/templates/common-cartago.asl}, {@code $moiseJar/...})
 * read as empty files.
 */
public final class JcmReader implements ProjectReader {
    static final String SETUP_GOAL = "jcm_setup";
    static final String FOCUS_GOAL = "jcm_focus";
    /** As JaCaMo's {@code jcm::focus_env_art}: five tries, 200 ms apart, for an artifact another agent makes. */
    static final int FOCUS_TRIES = 5;
    /**
     * {@code !jcm_focus(Workspace, Artifact, Where, Tries)}: focuses on the artifact; while it is
     * not there (another agent may make it as the system starts), waits 200 ms and tries again; at
     * the last try, says once where the focus was asked for and lets the agent go on, as JaCaMo does.
     */
    private static final List<String> FOCUS_PLANS = List.of(
            "@" + FOCUS_GOAL + "NotMade +!" + FOCUS_GOAL + "(W, A, At, 0) <- .print(At, \": error: focus '\", W, \".\", A, "
                    + "\"': no artifact '\", A, \"' in workspace '\", W, \"' (none made it in " + FOCUS_TRIES + " tries, "
                    + FOCUS_TRIES * 200 / 1000 + " s)\").",
            "@" + FOCUS_GOAL + " +!" + FOCUS_GOAL + "(W, A, _, _) <- lookupArtifact(A, Id)[wsp(W)]; focus(Id).",
            "@" + FOCUS_GOAL + "Again -!" + FOCUS_GOAL + "(W, A, At, Try) <- .wait(200); !" + FOCUS_GOAL + "(W, A, At, Try - 1).");
    private JcmProject project;

    @Override
    public boolean reads(Path file) {
        return file.getFileName().toString().endsWith(".jcm");
    }

    /** {@return the project file read, parsed (for its class path)} */
    public static JcmProject parse(Path file) throws UserError {
        try {
            return JcmParser.parse(file, Files.readString(file, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UserError(file + ": " + e.getMessage());
        } catch (JcmParser.JcmError e) {
            throw new UserError(e.getMessage());
        }
    }

    @Override
    public MasProject read(Path file) throws UserError {
        project = parse(file);
        Path dir = file.toAbsolutePath().getParent();
        var aslPath = new ArrayList<Path>();
        project.aslPath().forEach(p -> aslPath.add(dir.resolve(p)));
        for (String d : List.of("src/agt", "src/agt/inc")) {
            if (Files.isDirectory(dir.resolve(d))) {
                aslPath.add(dir.resolve(d));
            }
        }
        var specs = new ArrayList<MasProject.AgentSpec>();
        for (AgentDecl a : project.agents()) {
            var options = new HashMap<String, String>();
            if (a.beliefs() != null) {
                options.put("beliefs", a.beliefs());
            }
            if (a.goals() != null) {
                options.put("goals", a.goals());
            }
            String arch = a.archClass() != null ? a.archClass() : "jacabot.cartago.bridge.CAgentArch";
            specs.add(new MasProject.AgentSpec(a.name(), a.source(), options, arch, null, a.instances()));
        }
        return new MasProject(project.name(), CartagoEnvironment.class.getName(), List.of(), specs, aslPath, dir);
    }

    @Override
    public SourceResolver includes(SourceResolver files) {
        return (file, from) -> file.startsWith("$jacamoJar/") || file.startsWith("$moiseJar/")
                ? new SourceResolver.Source(file, "", null)
                : files.find(file, from);
    }

    @Override
    public void prepare(LocalMAS mas) throws UserError {
        var env = (CartagoEnvironment) mas.environment();
        var parser = new AslParser();
        for (WorkspaceDecl w : project.workspaces()) {
            Workspace ws = w.name().equals("main") ? env.workspace() : env.createWorkspace(w.name());
            for (ArtifactDecl a : w.artifacts()) {
                var params = new ArrayList<Object>();
                try {
                    if (!a.args().isEmpty() && parser.parseTerm("[" + a.args() + "]") instanceof ListTerm list) {
                        list.elements().forEach(t -> params.add(TermConverter.toJava(t)));
                    }
                    ws.createArtifact(a.name(), a.className(), params.toArray());
                } catch (AslSyntaxException e) {
                    throw new UserError(a.where() + ": error: the arguments of " + a.name() + " do not read: " + e.getMessage());
                } catch (CartagoException e) {
                    throw new UserError(a.where() + ": error: cannot make the artifact " + a.name() + ": " + e.getMessage());
                }
            }
        }
    }

    @Override
    public AgentProgram adapt(MasProject.AgentSpec spec, AgentProgram program, AslParser parser) throws UserError {
        AgentDecl decl = project.agents().stream().filter(a -> a.name().equals(spec.name())).findFirst().orElseThrow();
        var joins = new LinkedHashSet<String>(decl.join());
        project.workspaces().stream().filter(w -> w.agents().contains(decl.name())).forEach(w -> joins.add(w.name()));
        var steps = new ArrayList<String>();
        decl.focus().forEach(f -> joins.add(f.substring(0, f.lastIndexOf('.')))); // workspace.artifact, checked when read
        joins.forEach(w -> steps.add("joinWorkspace(" + quoted(w) + ", _)"));
        for (int i = 0; i < decl.focus().size(); i++) {
            String f = decl.focus().get(i);
            int dot = f.lastIndexOf('.');
            steps.add("!" + FOCUS_GOAL + "(" + quoted(f.substring(0, dot)) + ", " + quoted(f.substring(dot + 1)) + ", "
                    + quoted(decl.focusAt().get(i)) + ", " + FOCUS_TRIES + ")");
        }
        if (steps.isEmpty()) {
            return program;
        }
        try {
            Plan setup = parser.parsePlan("@" + SETUP_GOAL + "[atomic] +!" + SETUP_GOAL + " <- " + String.join("; ", steps) + ".");
            var plans = new ArrayList<Plan>();
            plans.add(setup);
            if (!decl.focus().isEmpty()) {
                for (String plan : FOCUS_PLANS) {
                    plans.add(parser.parsePlan(plan));
                }
            }
            plans.addAll(program.plans());
            var goals = new ArrayList<Literal>();
            goals.add(Literal.atom(SETUP_GOAL));
            goals.addAll(program.goals());
            return new AgentProgram(program.file(), program.beliefs(), goals, plans, program.functions());
        } catch (AslSyntaxException e) {
            throw new UserError(project.file() + ": error: agent " + decl.name() + ": " + e.getMessage());
        }
    }

    private static String quoted(String s) {
        return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
    }

    @Override
    public String optionPlace(MasProject.AgentSpec spec, String option) {
        return project.agents().stream().filter(a -> a.name().equals(spec.name())).findFirst()
                .map(a -> a.optionsAt().get(option)).orElse(null);
    }

    /** The class path entries of a project's {@code class-path:}. */
    public static List<String> classPath(Path file) throws UserError {
        return parse(file).classPath();
    }

}
