package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The launchers' TLS options on loopback: {@code jacabot run --tls-store} (a second JVM; its
 * middleware behind a TLS relay) and {@code jacabot controller --tls-store}, with key stores made by
 * the JDK's keytool. The controller drives over TLS; one that does not trust the key never connects.
 */
class TlsLaunchersTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    private static final String PASSWORD = "changeit";

    private static void keytool(String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "keytool").toString()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0, said);
    }

    /** The middleware's key store (key and certificate for 127.0.0.1) and a store trusting that certificate. */
    private static void stores(Path dir, String name) throws Exception {
        Path key = dir.resolve(name + ".p12"), cert = dir.resolve(name + ".cer");
        keytool("-genkeypair", "-alias", "link", "-keyalg", "EC", "-groupname", "secp256r1", "-dname",
                "CN=jacabot middleware", "-ext", "SAN=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12",
                "-keystore", key.toString(), "-storepass", PASSWORD);
        keytool("-exportcert", "-alias", "link", "-keystore", key.toString(), "-storepass", PASSWORD, "-file", cert.toString());
        keytool("-importcert", "-noprompt", "-alias", "link", "-file", cert.toString(), "-storetype", "PKCS12",
                "-keystore", dir.resolve(name + "-trust.p12").toString(), "-storepass", PASSWORD);
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    @Test
    void runAndControllerTalkOverTlsAndAnUntrustingControllerNeverConnects(@TempDir Path dir) throws Exception {
        stores(dir, "middleware");
        stores(dir, "stranger");
        Path password = dir.resolve("password");
        Files.writeString(password, PASSWORD + "\n");
        Path secret = dir.resolve("secret");
        int port = freePort();
        Path agentOut = dir.resolve("agent.txt");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process agent = new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "jacabot.app.cli.JacabotCommand", "run", ROOT.resolve("agents/src/main/asl/obstacle-avoidance.mas2j").toString(),
                "--port", String.valueOf(port), "--secret-file", secret.toString(),
                "--tls-store", dir.resolve("middleware.p12").toString(), "--tls-password-file", password.toString())
                .redirectErrorStream(true).redirectOutput(agentOut.toFile()).start();
        try {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (!Files.readString(agentOut).contains("TLS on 127.0.0.1:" + port) && System.nanoTime() < end) {
                assertTrue(agent.isAlive(), Files.readString(agentOut));
                Thread.sleep(50);
            }
            String[] stranger = CliRun.run("controller", "--world", ROOT.resolve("worlds/obstacle-avoidance.json").toString(),
                    "--port", String.valueOf(port), "--secret-file", secret.toString(), "--seconds", "1",
                    "--tls-store", dir.resolve("stranger-trust.p12").toString(), "--tls-password-file", password.toString());
            assertEquals("0", stranger[0], stranger[2]);
            assertTrue(!stranger[2].contains("connected to the middleware"), stranger[2]);
            assertTrue(stranger[2].contains("PKIX") || stranger[2].contains("certificate"), stranger[2]);

            String[] c = CliRun.run("controller", "--world", ROOT.resolve("worlds/obstacle-avoidance.json").toString(),
                    "--port", String.valueOf(port), "--secret-file", secret.toString(), "--seconds", "3",
                    "--tls-store", dir.resolve("middleware-trust.p12").toString(), "--tls-password-file", password.toString());
            assertEquals("0", c[0], c[2]);
            assertTrue(c[1].contains("over TLS"), c[1]);
            assertTrue(c[2].contains("connected to the middleware at 127.0.0.1:" + port), c[2]);
            end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!Files.readString(agentOut).contains("Acquiring data") && System.nanoTime() < end) {
                Thread.sleep(50);
            }
            assertTrue(Files.readString(agentOut).contains("Acquiring data"), "the agent perceived: " + Files.readString(agentOut));
        } finally {
            agent.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void aMissingStoreOrPasswordIsAUserError(@TempDir Path dir) throws Exception {
        String world = ROOT.resolve("worlds/obstacle-avoidance.json").toString();
        String[] r = CliRun.run("controller", "--world", world, "--tls-store", dir.resolve("none.p12").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].startsWith("error: --tls-store needs --tls-password-file FILE"), r[2]);
        Files.writeString(dir.resolve("pw"), "x\n");
        r = CliRun.run("controller", "--world", world, "--tls-store", dir.resolve("none.p12").toString(),
                "--tls-password-file", dir.resolve("pw").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].startsWith("error: " + dir.resolve("none.p12") + ": cannot open the key store"), r[2]);
        assertTrue(!r[2].contains("\tat "), r[2]);
    }
}
