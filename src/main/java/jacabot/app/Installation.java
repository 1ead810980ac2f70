package jacabot.app;

import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Where jacabot is installed ({@code gradle installDist}: {@code bin/}, {@code lib/}, and the
 * bundled {@code worlds/}, {@code agents/src/main/asl/} and {@code examples/}, at their paths in
 * the repository), so that experiment names work from any folder.
 *
 * <p>The one rule for a file the user names ({@code --agent}, {@code --world}, {@code --worlds},
 * {@code jacabot run FILE}, {@code jacabot world view FILE}, ...; {@link #locate}): relative to the
 * current folder first, then to the installation. So {@code agents/src/main/asl/as-published/navigation.asl}
 * works in a checkout and from any folder. Outputs ({@code --out}, {@code runs/}) go to the current folder.
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
     * {@return a file the user named}: as given when it is absolute or exists from the current
     * folder, else the installation's file of that path when there is one, else as given (so that
     * a message names what the user typed)
     */
    public static Path locate(Path named) {
        if (named.isAbsolute() || Files.exists(named)) {
            return named;
        }
        return home().map(h -> h.resolve(named)).filter(Files::exists).orElse(named);
    }

    /**
     * Resolves a bundled file named relative to the repository or the installation (e.g.
     * {@code worlds/navigation.json}): inside the installation when jacabot runs installed,
     * else relative to the current folder (a checkout, {@code gradle run}).
     */
    public static Path resolve(String bundled) {
        return home().map(h -> h.resolve(bundled)).filter(Files::exists).orElse(Path.of(bundled));
    }

    /**
     * {@return the name to show for {@code file}}: a bundled file by its path inside the installation
     * ({@code worlds/navigation.json}, the path a checkout has, as {@code gradle run} shows it), any
     * other as given
     */
    public static String shown(Path file) {
        return home().map(h -> h.toAbsolutePath().normalize())
                .filter(h -> file.toAbsolutePath().normalize().startsWith(h))
                .map(h -> h.relativize(file.toAbsolutePath().normalize()).toString())
                .orElse(file.toString());
    }
}
