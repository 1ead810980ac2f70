package jacabot.app.bench;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The class-data sharing archive {@code gradle installDist} writes beside the launcher's jars
 * ({@code lib/jacabot.jsa}), so that a bench runs our JVMs as {@code bin/jacabot} does. The
 * archive only maps for the class path it was made with (the start script's, jar by jar in its
 * order) and the JVM that made it; this asks the JVM before using it.
 */
final class SharedArchive {
    static final String FILE_NAME = "jacabot.jsa";

    private SharedArchive() {
    }

    /** {@return the JVM options that map the archive beside this class path's jars, or none when there is none this JVM can map} */
    static List<String> optionsFor(String classpath) {
        Path archive = find(classpath);
        if (archive == null) {
            return List.of();
        }
        String option = "-XX:SharedArchiveFile=" + archive;
        // -Xshare:on makes a JVM that cannot map it fail instead of running on without it
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        try {
            Process p = new ProcessBuilder(java, "-Xshare:on", option, "-cp", classpath, "-version")
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            if (!p.waitFor(1, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                return List.of();
            }
            return p.exitValue() == 0 ? List.of(option, "-Xlog:cds=off", "-Xlog:cds+dynamic=off") : List.of();
        } catch (IOException e) {
            return List.of();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return List.of();
        }
    }

    /** {@return the archive in the folder of one of the class path's jars, or null} */
    static Path find(String classpath) {
        for (String entry : classpath.split(File.pathSeparator)) {
            if (!entry.endsWith(".jar")) {
                continue;
            }
            Path parent = Path.of(entry).toAbsolutePath().getParent();
            if (parent != null && Files.isRegularFile(parent.resolve(FILE_NAME))) {
                return parent.resolve(FILE_NAME);
            }
        }
        return null;
    }
}
