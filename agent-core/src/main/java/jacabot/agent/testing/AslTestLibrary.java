package jacabot.agent.testing;

import jacabot.agent.parser.SourceResolver;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

/**
 * jacabot's AgentSpeak test library (resources {@code jacabot/agent/testing/lib/}): the tester
 * agent, its assertions and the test manager, under the names Jason 3.2 gives them. A test
 * file's {@code { include("tester_agent.asl") }} (or Jason's
 * {@code "$jasonJar/test/jason/inc/tester_agent.asl"}) reads them when no file of that name is
 * beside it or on its source path: a project's own copy wins.
 */
public final class AslTestLibrary {
    static final String FOLDER = "jacabot/agent/testing/lib/";
    static final Set<String> FILES = Set.of("tester_agent.asl", "test_assert.asl", "test_manager.asl");

    private AslTestLibrary() {
    }

    /** Files first (beside the including file, the source path, the working directory), then the library. */
    public static SourceResolver resolver(List<Path> sourcePath) {
        SourceResolver files = SourceResolver.files(sourcePath);
        return (file, from) -> {
            if (from != null && from.location() != null && from.location().startsWith(FOLDER)) {
                return library(file); // the library's own includes
            }
            SourceResolver.Source found = file.startsWith("$") ? null : files.find(file, from);
            return found != null ? found : library(file);
        };
    }

    /** The library's source for a name ending in one of its files, or null. */
    public static SourceResolver.Source library(String file) throws IOException {
        String base = file.substring(Math.max(file.lastIndexOf('/'), file.lastIndexOf('\\')) + 1);
        if (!FILES.contains(base)) {
            return null;
        }
        try (InputStream in = AslTestLibrary.class.getClassLoader().getResourceAsStream(FOLDER + base)) {
            if (in == null) {
                throw new IOException("jacabot's test library lacks " + base);
            }
            return new SourceResolver.Source("jacabot-test-library/" + base, new String(in.readAllBytes(), StandardCharsets.UTF_8),
                    FOLDER + base);
        }
    }
}
