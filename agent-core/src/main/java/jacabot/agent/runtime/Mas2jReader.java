package jacabot.agent.runtime;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.parser.Mas2jLexer;
import jacabot.agent.parser.Mas2jParser;
import jacabot.agent.parser.SyntaxError;
import jacabot.agent.syntax.SourceInfo;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;

/** Reads {@code .mas2j} project files. */
public final class Mas2jReader {
    private Mas2jReader() {
    }

    public static MasProject read(Path file) throws IOException, AslSyntaxException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        var errors = new ArrayList<SyntaxError>();
        var listener = new BaseErrorListener() {
            @Override
            public void syntaxError(Recognizer<?, ?> r, Object o, int line, int col, String msg, RecognitionException e) {
                errors.add(new SyntaxError(new SourceInfo(file.toString(), line, col + 1), SyntaxError.inOurWords(msg, r, e)));
            }
        };
        var lexer = new Mas2jLexer(CharStreams.fromString(text));
        lexer.removeErrorListeners();
        lexer.addErrorListener(listener);
        var parser = new Mas2jParser(new CommonTokenStream(lexer));
        parser.removeErrorListeners();
        parser.addErrorListener(listener);
        var tree = parser.project();
        if (!errors.isEmpty()) {
            throw new AslSyntaxException(errors);
        }
        Path dir = file.toAbsolutePath().getParent();
        String env = null;
        var envArgs = new ArrayList<String>();
        var agents = new ArrayList<MasProject.AgentSpec>();
        var sourcePath = new ArrayList<Path>();
        for (Mas2jParser.SettingContext s : tree.setting()) {
            if (s instanceof Mas2jParser.EnvironmentContext e) {
                env = e.className().getText();
                if (e.arguments() != null) {
                    for (Mas2jParser.ArgumentContext a : e.arguments().argument()) {
                        envArgs.add(unquote(a.getText()));
                    }
                }
            } else if (s instanceof Mas2jParser.AgentsContext a) {
                for (Mas2jParser.AgentDeclContext d : a.agentDecl()) {
                    agents.add(agent(d));
                }
            } else if (s instanceof Mas2jParser.InfrastructureContext inf) {
                String name = inf.ID().getText();
                if (!name.equalsIgnoreCase("Local")) {
                    // running another infrastructure as Local would silently change the system
                    throw new AslSyntaxException(List.of(new SyntaxError(new SourceInfo(file.toString(),
                            inf.getStart().getLine(), inf.getStart().getCharPositionInLine() + 1),
                            "infrastructure '" + name + "' is not supported: jacabot runs the Local infrastructure only")));
                }
            } else if (s instanceof Mas2jParser.AslSourcePathContext p) {
                p.STRING().forEach(t -> sourcePath.add(dir.resolve(unquote(t.getText()))));
            }
        }
        return new MasProject(tree.ID().getText(), env, envArgs, agents, sourcePath, dir);
    }

    private static MasProject.AgentSpec agent(Mas2jParser.AgentDeclContext d) {
        String name = d.agentName().getText();
        String file = d.fileName() == null ? name + ".asl" : unquote(d.fileName().getText());
        if (!file.endsWith(".asl")) {
            file = file + ".asl"; // Jason adds the extension: agents: bob bob_v2;
        }
        var options = new LinkedHashMap<String, String>();
        if (d.optionList() != null) {
            for (Mas2jParser.OptionContext o : d.optionList().option()) {
                options.put(o.ID(0).getText(), unquote(o.getChild(2).getText()));
            }
        }
        String arch = null;
        String agentClass = null;
        for (Mas2jParser.ArchClassContext c : d.archClass()) {
            if (c.kind.getText().equals("agentArchClass")) {
                arch = c.className().getText();
            } else if (c.kind.getText().equals("agentClass")) {
                agentClass = c.className().getText();
            }
        }
        int n = d.NUMBER().isEmpty() ? 1 : Integer.parseInt(d.NUMBER(0).getText());
        return new MasProject.AgentSpec(name, file, options, arch, agentClass, n);
    }

    private static String unquote(String s) {
        return s.length() >= 2 && s.startsWith("\"") && s.endsWith("\"") ? s.substring(1, s.length() - 1) : s;
    }
}
