package jacabot.agent.parser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Included sources from files and from a jar on the class path, relative to the including source. */
class SourceResolverTest {
    @Test
    void aPackagedAgentIncludesFromItsOwnFolderInTheJar(@TempDir Path dir) throws Exception {
        try (var loader = jar(dir, Map.of(
                "asl/agent.asl", "a(1).\n{ include(\"common/start.asl\") }\n+!after <- true.\n",
                "asl/common/start.asl", "!start.\n+!start <- !more.\n{ include(\"../more.asl\") }\n",
                "asl/more.asl", "+!more <- true.\n"))) {
            var parser = new AslParser(SourceResolver.resources(loader));
            var program = parser.parse(source(loader, "agents/agent.asl", "asl/agent.asl"));
            // the included plans sit where the directive is, in the included files' order
            assertEquals(List.of("+!start", "+!more", "+!after"),
                    program.plans().stream().map(p -> p.trigger().toString()).toList());
            assertEquals(1, program.goals().size());
            assertEquals("agents/common/start.asl", program.plans().get(0).source().file(), "named beside the includer");
        }
    }

    @Test
    void aMissingOrBrokenIncludeNamesItsPlace(@TempDir Path dir) throws Exception {
        try (var loader = jar(dir, Map.of(
                "asl/agent.asl", "a(1).\n  { include(\"common/missing.asl\") }\n",
                "asl/broken.asl", "{ include(\"common/bad.asl\") }\n",
                "asl/common/bad.asl", "+!g <- .\n",
                "asl/self.asl", "{ include(\"self.asl\") }\n"))) {
            var parser = new AslParser(SourceResolver.resources(loader));
            var e = assertThrows(AslSyntaxException.class, () -> parser.parse(source(loader, "agents/agent.asl", "asl/agent.asl")));
            assertEquals("agents/agent.asl:2:3: error: included file 'common/missing.asl' not found", e.getMessage());
            e = assertThrows(AslSyntaxException.class, () -> parser.parse(source(loader, "agents/broken.asl", "asl/broken.asl")));
            assertTrue(e.getMessage().startsWith("agents/common/bad.asl:1:"), e.getMessage());
            e = assertThrows(AslSyntaxException.class, () -> parser.parse(source(loader, "self.asl", "asl/self.asl")));
            assertEquals("self.asl:1:1: error: file 'self.asl' includes itself", e.getMessage());
        }
    }

    @Test
    void resourcesAreNotLookedUpOutsideTheClassPathOrWithoutAPlace(@TempDir Path dir) throws Exception {
        try (var loader = jar(dir, Map.of("asl/a.asl", "a.\n", "x.asl", "x.\n"))) {
            var resources = SourceResolver.resources(loader);
            var from = new SourceResolver.Source("a.asl", "", "asl/a.asl");
            assertEquals("x.\n", resources.find("../x.asl", from).text());
            assertNull(resources.find("../../x.asl", from));
            assertNull(resources.find("/x.asl", from));
            assertNull(resources.find("x.asl", new SourceResolver.Source("a.asl", "", null)));
        }
    }

    @Test
    void filesAreLookedUpBesideTheIncluderThenOnTheSourcePath(@TempDir Path dir) throws Exception {
        Files.createDirectories(dir.resolve("agents/common"));
        Files.createDirectories(dir.resolve("lib"));
        Files.writeString(dir.resolve("agents/common/start.asl"), "+!start <- true.\n");
        Files.writeString(dir.resolve("lib/util.asl"), "+!util <- true.\n");
        Files.writeString(dir.resolve("agents/a.asl"), "{ include(\"common/start.asl\") }\n{ include(\"util.asl\") }\n");
        var program = new AslParser(List.of(dir.resolve("lib"))).parseFile(dir.resolve("agents/a.asl"));
        assertEquals(2, program.plans().size());
        var e = assertThrows(AslSyntaxException.class, () -> new AslParser().parseFile(dir.resolve("agents/a.asl")));
        assertEquals(dir.resolve("agents/a.asl") + ":2:1: error: included file 'util.asl' not found", e.getMessage());
    }

    private static SourceResolver.Source source(ClassLoader loader, String name, String resource) throws Exception {
        try (var in = loader.getResourceAsStream(resource)) {
            return new SourceResolver.Source(name, new String(in.readAllBytes(), StandardCharsets.UTF_8), resource);
        }
    }

    private static URLClassLoader jar(Path dir, Map<String, String> entries) throws Exception {
        Path jar = dir.resolve("agents.jar");
        try (OutputStream out = Files.newOutputStream(jar); var j = new JarOutputStream(out)) {
            for (var e : entries.entrySet()) {
                j.putNextEntry(new JarEntry(e.getKey()));
                j.write(e.getValue().getBytes(StandardCharsets.UTF_8));
                j.closeEntry();
            }
        }
        return new URLClassLoader(new URL[] {jar.toUri().toURL()}, null);
    }
}
