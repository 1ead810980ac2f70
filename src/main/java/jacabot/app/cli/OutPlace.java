package jacabot.app.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;

/**
 * Where a command writes ({@code --out}): made and checked before the work, so that a place that
 * cannot be written is one plain line ({@code --out /proc/x: cannot make the directory (no such
 * file or directory); choose another with --out DIR}), not an exception's class after the run.
 */
final class OutPlace {
    private OutPlace() {
    }

    /** {@return why a file or directory could not be made, in a few words, without the exception's class} */
    static String whyNot(IOException e) {
        if (e instanceof FileAlreadyExistsException) {
            return "a file of that name exists";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such file or directory";
        }
        if (e instanceof NotDirectoryException) {
            return "not a directory";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason().toLowerCase(java.util.Locale.ROOT);
        }
        return e.getMessage() != null ? e.getMessage() : "it cannot be written";
    }

    /** Makes the directory {@code option} names (and its parents) and checks it can be written. */
    static void directory(String option, Path dir) {
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw new UserError(option + " " + dir + ": cannot make the directory (" + whyNot(e) + "); choose another with "
                    + option + " DIR");
        }
        if (!Files.isWritable(dir)) {
            throw new UserError(option + " " + dir + ": not writable; choose another with " + option + " DIR");
        }
    }

    /** Makes the folder of the file {@code option} names and checks the file can be written there. */
    static void file(String option, Path file) {
        Path parent = file.toAbsolutePath().getParent();
        if (Files.isDirectory(file)) {
            throw new UserError(option + " " + file + ": a directory; give a file's name");
        }
        try {
            if (parent != null) {
                Files.createDirectories(parent);
            }
        } catch (IOException e) {
            throw new UserError(option + " " + file + ": cannot make its folder (" + whyNot(e) + ")");
        }
        if (parent != null && !Files.isWritable(parent)) {
            throw new UserError(option + " " + file + ": its folder is not writable");
        }
    }

    /** {@return the user error of a file {@code option} names that could not be written} */
    static UserError cannotWrite(String option, Path file, IOException e) {
        return new UserError(option + " " + file + ": cannot write it (" + whyNot(e) + ")");
    }
}
