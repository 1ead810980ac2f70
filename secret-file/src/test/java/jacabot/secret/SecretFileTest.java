package jacabot.secret;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The secret's file: made for its owner only, published whole, never replaced, refused when others may read it. */
class SecretFileTest {
    @Test
    void aMissingFileIsMadeForItsOwnerAndReadBackNotMadeAgain(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("keys").resolve("secret");
        assertEquals("00ff", SecretFile.loadOrCreate(file, "test secret", "00ff"));
        assertEquals("00ff", SecretFile.loadOrCreate(file, "test secret", "1234"), "the file's key, not the fresh one");
        assertEquals(PosixFilePermissions.fromString("rw-------"), Files.getPosixFilePermissions(file));
        assertEquals(PosixFilePermissions.fromString("rwx------"), Files.getPosixFilePermissions(file.getParent()));
        try (Stream<Path> left = Files.list(file.getParent())) {
            assertEquals(List.of(file), left.toList(), "no temporary file left beside it");
        }
    }

    @Test
    void publishingNeverReplacesAKeyAlreadyThere(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("secret");
        assertTrue(SecretFile.publish(file, "aa\n"));
        assertFalse(SecretFile.publish(file, "bb\n"), "the second publisher loses");
        assertEquals("aa", SecretFile.read(file, "test secret"));
    }

    @Test
    void aFileOthersMayReadIsRefusedWithTheCommandThatFixesIt(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("secret");
        Files.writeString(file, "abcd\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        IOException e = assertThrows(IOException.class, () -> SecretFile.read(file, "test secret"));
        assertEquals("the test secret " + file + " may be read by other users; run: chmod 600 " + file, e.getMessage());
    }
}
