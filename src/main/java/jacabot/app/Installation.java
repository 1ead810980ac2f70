package jacabot.app;

import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Where jacabot is installed ({@code gradle installDist}: {@code bin/}, {@code lib/}, and the
 * bundled {@code worlds/}, {@code agents/} and {@code examples/}), so that experiment names
 * work from any folder. Paths the user types stay relative to the current folder.
 */
public final class Installation {
    private Installation() {
    }

    /** {@return the installation's folder: the parent of the {@code lib/} holding jacabot's jar, if so installed} */
    public static Optional<Path> home() {
        String forced = System.getProperty("jacabot.home");
        if (forced != null) {
            return Optional.of(Path.of(forced));
        }
        try {
            var source = Installation.class.getProtectionDomain().getCodeSource();
            if (source == null) {
                return Optional.empty();
            }
            Path jar = Path.of(source.getLocation().toURI());
            Path lib = jar.getParent();
            if (Files.isRegularFile(jar) && lib != null && lib.getFileName() != null
                    && lib.getFileName().toString().equals("lib") && Files.isDirectory(lib.getParent().resolve("worlds"))) {
                return Optional.of(lib.getParent());
            }
        } catch (URISyntaxException | SecurityException | IllegalArgumentException e) {
            // not from a jar on the file system
        }
        return Optional.empty();
    }

    /**
     * Resolves a bundled file named relative to the repository or the installation (e.g.
     * {@code worlds/navigation.json}): inside the installation when jacabot runs installed,
     * else relative to the current folder (a checkout, {@code gradle run}).
     */
    public static Path resolve(String bundled) {
        return home().map(h -> h.resolve(bundled)).filter(Files::exists).orElse(Path.of(bundled));
    }
}
