package jacabot.app.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The bench maps the launcher's class-data sharing archive only where the JVM can use it. */
class SharedArchiveTest {
    @TempDir
    Path dir;

    /** A jar holding one class with an empty main, in folder {@code lib}. */
    private Path jar(String folder) throws IOException {
        Path src = Files.createDirectories(dir.resolve("src"));
        Files.writeString(src.resolve("Hi.java"), "public class Hi { public static void main(String[] a) { } }");
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", src.toString(), src.resolve("Hi.java").toString()));
        Path jar = Files.createDirectories(dir.resolve(folder)).resolve("hi.jar");
        try (var out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new JarEntry("Hi.class"));
            out.write(Files.readAllBytes(src.resolve("Hi.class")));
            out.closeEntry();
        }
        return jar;
    }

    private static void dump(Path jar, Path archive) throws IOException, InterruptedException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-XX:ArchiveClassesAtExit=" + archive, "-Xlog:cds=off", "-cp", jar.toString(), "Hi")
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        assertEquals(0, p.waitFor());
        assertTrue(Files.isRegularFile(archive), "the JVM wrote no archive");
    }

    @Test
    void noArchiveBesideTheJarsMeansNoOption() throws IOException {
        Path jar = jar("lib");
        assertNull(SharedArchive.find(jar.toString()));
        assertEquals(List.of(), SharedArchive.optionsFor(jar.toString()));
    }

    @Test
    void anArchiveMadeForThisClassPathIsMapped() throws Exception {
        Path jar = jar("lib");
        Path archive = jar.resolveSibling(SharedArchive.FILE_NAME);
        dump(jar, archive);
        assertEquals(archive.toAbsolutePath(), SharedArchive.find(jar.toString()));
        assertEquals(List.of("-XX:SharedArchiveFile=" + archive.toAbsolutePath(), "-Xlog:cds=off", "-Xlog:cds+dynamic=off"),
                SharedArchive.optionsFor(jar.toString()));
    }

    @Test
    void anArchiveMadeForOtherJarsOrNoArchiveAtAllIsLeftOut() throws Exception {
        Path jar = jar("lib");
        Path archive = jar.resolveSibling(SharedArchive.FILE_NAME);
        dump(jar, archive);
        // the same jar and archive moved to another folder: the class path the archive records differs
        Path moved = Files.createDirectories(dir.resolve("moved"));
        Files.copy(jar, moved.resolve("hi.jar"));
        Files.copy(archive, moved.resolve(SharedArchive.FILE_NAME));
        assertEquals(List.of(), SharedArchive.optionsFor(moved.resolve("hi.jar").toString()));
        // a file that is no archive
        Path other = jar("garbage");
        try (OutputStream out = Files.newOutputStream(other.resolveSibling(SharedArchive.FILE_NAME))) {
            out.write(new byte[4096]);
        }
        assertEquals(List.of(), SharedArchive.optionsFor(other.toString()));
    }
}
