package jacabot.experiments.link;

import static jacabot.experiments.link.LinkTestSupport.await;
import static jacabot.experiments.link.LinkTestSupport.waitFor;
import static jacabot.experiments.link.LinkTestSupport.world;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.Command;
import jacabot.robot.link.LinkSecret;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The optional TLS mode (for a controller on another machine), with the JDK's own SSLSocket and a
 * key made by the JDK's keytool: the robot is driven over it, and a controller that does not trust
 * the middleware's certificate never connects.
 */
class TlsLinkTest {
    private static final char[] PASSWORD = "changeit".toCharArray();

    private static KeyStore keyStore(Path dir) throws Exception {
        Path p12 = dir.resolve("middleware.p12");
        String keytool = Path.of(System.getProperty("java.home"), "bin", "keytool").toString();
        Process p = new ProcessBuilder(keytool, "-genkeypair", "-alias", "link", "-keyalg", "EC", "-groupname", "secp256r1",
                "-dname", "CN=jacabot middleware", "-ext", "SAN=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12",
                "-keystore", p12.toString(), "-storepass", new String(PASSWORD)).redirectErrorStream(true).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0, new String(p.getInputStream().readAllBytes()));
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(p12)) {
            ks.load(in, PASSWORD);
        }
        return ks;
    }

    private static SSLContext server(KeyStore ks) throws Exception {
        var kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(ks, PASSWORD);
        SSLContext c = SSLContext.getInstance("TLS");
        c.init(kmf.getKeyManagers(), null, null);
        return c;
    }

    private static SSLContext client(KeyStore trusted) throws Exception {
        var tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
        tmf.init(trusted);
        SSLContext c = SSLContext.getInstance("TLS");
        c.init(null, tmf.getTrustManagers(), null);
        return c;
    }

    private static KeyStore trusting(KeyStore ks) throws Exception {
        KeyStore ts = KeyStore.getInstance("PKCS12");
        ts.load(null, null);
        ts.setCertificateEntry("link", ks.getCertificate("link"));
        return ts;
    }

    @Test
    void theRobotIsDrivenOverTlsAndAnUntrustedMiddlewareIsRefused(@TempDir Path dir) throws Exception {
        KeyStore ks = keyStore(dir);
        LinkSecret secret = LinkSecret.random();
        List<String> log = new CopyOnWriteArrayList<>();
        try (MiddlewareLink m = MiddlewareLink.open(LinkConfig.defaults().withPort(0).withSecret(secret)
                .withLog(log::add).withTls(server(ks)))) {
            var cc = ControllerConfig.defaults().withAddress("127.0.0.1", m.port()).withSecret(secret)
                    .withSpeedFactor(5).withLog(log::add);
            try (RobotController c = new RobotController(world("navigation"), cc.withTls(client(trusting(ks))))) {
                c.start();
                c.runner().start();
                await(m, e -> e instanceof LinkEvent.Connected);
                assertTrue(m.send(Command.forward()));
                await(m, LinkTestSupport.wheels(50, 50));
                c.runner().stop();
            }
            // a controller that trusts another certificate (a stranger's middleware, as it sees it)
            KeyStore other = keyStore(Files.createDirectories(dir.resolve("other")));
            try (RobotController c = new RobotController(world("navigation"), cc.withTls(client(trusting(other)))
                    .withBackoff(50, 100))) {
                c.start();
                waitFor(() -> c.lastProblem() != null);
                assertFalse(c.isConnected());
                assertTrue(c.lastProblem().contains("PKIX") || c.lastProblem().toLowerCase().contains("certif"),
                        c.lastProblem());
            }
            assertEquals(1, log.stream().filter(l -> l.startsWith("controller connected")).count(), log.toString());
        }
    }
}
