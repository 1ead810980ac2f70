package jacabot.agent.parser;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Where the sources named by {@code { include("f.asl") }} are read from: files on disk, or
 * resources on the class path (agents packaged in a jar), relative to the source that includes them.
 */
public interface SourceResolver {
    /**
     * One AgentSpeak source.
     *
     * @param name     its name in messages ({@code name:line:col})
     * @param location where it is, for the resolver: a file's absolute path or a resource's path; null when
     *                 the text has no place (includes are then looked up as if from the working directory)
     */
    record Source(String name, String text, String location) {
    }

    /** {@return the source that {@code file}, included from {@code from}, names; null when there is none} */
    Source find(String file, Source from) throws IOException;

    /**
     * Files: the including file's directory, then {@code sourcePath}, then the working directory
     * (an absolute name only as given).
     */
    static SourceResolver files(List<Path> sourcePath) {
        List<Path> path = List.copyOf(sourcePath);
        return (file, from) -> {
            Path dir = from != null && from.location() != null ? Path.of(from.location()).getParent() : null;
            Path c = findFile(file, dir, path);
            return c == null ? null
                    : new Source(c.toString(), Files.readString(c, StandardCharsets.UTF_8), c.toAbsolutePath().normalize().toString());
        };
    }

    /**
     * {@return the first regular file that {@code file} names: in {@code dir} (when not null), then on
     * {@code sourcePath}, then as given (an absolute name only as given); null when there is none}
     */
    static Path findFile(String file, Path dir, List<Path> sourcePath) {
        Path p = Path.of(file);
        var candidates = new ArrayList<Path>();
        if (!p.isAbsolute()) {
            if (dir != null) {
                candidates.add(dir.resolve(file));
            }
            sourcePath.forEach(d -> candidates.add(d.resolve(file)));
        }
        candidates.add(p);
        return candidates.stream().filter(Files::isRegularFile).findFirst().orElse(null);
    }

    /**
     * Class path resources, relative to the including resource's folder: {@code common/x.asl} included
     * from the resource {@code asl/a.asl} is {@code asl/common/x.asl}, and is named in messages
     * beside the including source's name (from {@code agents/src/main/asl/a.asl}:
     * {@code agents/src/main/asl/common/x.asl}).
     */
    static SourceResolver resources(ClassLoader loader) {
        return (file, from) -> {
            if (from == null || from.location() == null || file.startsWith("/")) {
                return null;
            }
            String location = normalize(folder(from.location()) + file);
            if (location == null) {
                return null;
            }
            try (InputStream in = loader.getResourceAsStream(location)) {
                return in == null ? null
                        : new Source(folder(from.name()) + file, new String(in.readAllBytes(), StandardCharsets.UTF_8), location);
            }
        };
    }

    private static String folder(String name) {
        int slash = Math.max(name.lastIndexOf('/'), name.lastIndexOf('\\'));
        return name.substring(0, slash + 1);
    }

    /** {@code a/b/../c} is {@code a/c}; null for a name that climbs out of the class path's root. */
    private static String normalize(String location) {
        var parts = new ArrayList<String>();
        for (String part : location.split("/")) {
            if (part.equals("..")) {
                if (parts.isEmpty()) {
                    return null;
                }
                parts.remove(parts.size() - 1);
            } else if (!part.isEmpty() && !part.equals(".")) {
                parts.add(part);
            }
        }
        return String.join("/", parts);
    }
}
