package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The launchers' TLS stores: a keytool store opens, a wrong password or a missing file is one clear line. */
class LinkTlsTest {
    @Test
    void aKeytoolStoreOpensAndBadOnesSayWhy(@TempDir Path dir) throws Exception {
        Path store = dir.resolve("middleware.p12");
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "keytool").toString(),
                "-genkeypair", "-alias", "link", "-keyalg", "EC", "-groupname", "secp256r1", "-dname", "CN=test",
                "-validity", "2", "-storetype", "PKCS12", "-keystore", store.toString(), "-storepass", "changeit")
                .redirectErrorStream(true).start();
        p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0, "keytool failed");
        Path password = dir.resolve("pw");
        Files.writeString(password, "changeit\nignored\n");
        assertArrayEquals("changeit".toCharArray(), LinkTls.readPassword(password));
        assertEquals("TLS", LinkTls.fromStore(store, password).getProtocol());

        IOException wrong = assertThrows(IOException.class, () -> LinkTls.fromStore(store, "nope".toCharArray()));
        assertTrue(wrong.getMessage().startsWith(store + ": cannot open the key store ("), wrong.getMessage());
        IOException missing = assertThrows(IOException.class, () -> LinkTls.fromStore(dir.resolve("none.p12"), password));
        assertEquals(dir.resolve("none.p12") + ": cannot open the key store (no such file)", missing.getMessage());
        IOException noPassword = assertThrows(IOException.class, () -> LinkTls.readPassword(dir.resolve("none")));
        assertTrue(noPassword.getMessage().startsWith(dir.resolve("none") + ": cannot read the password file"), noPassword.getMessage());
    }
}
