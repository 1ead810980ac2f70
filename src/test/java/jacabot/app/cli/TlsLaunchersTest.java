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
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
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
    @Timeout(value = 10, unit = TimeUnit.MINUTES) // three JVMs, each waited for on a condition (see awaitOutput)
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
            awaitOutput(agent, agentOut, s -> s.contains("TLS on 127.0.0.1:" + port));
            // each controller runs in a JVM of its own until what it should say shows (a loaded machine
            // takes seconds to shake hands): no fixed budget of real time decides the outcome
            String world = ROOT.resolve("worlds/obstacle-avoidance.json").toString();
            Path strangerOut = dir.resolve("stranger.txt");
            Process stranger = controller(java, strangerOut, "--world", world, "--port", String.valueOf(port),
                    "--secret-file", secret.toString(), "--seconds", "600",
                    "--tls-store", dir.resolve("stranger-trust.p12").toString(), "--tls-password-file", password.toString());
            try {
                String said = awaitOutput(stranger, strangerOut, s -> s.contains("PKIX") || s.contains("certificate"));
                assertTrue(stranger.isAlive(), "the untrusting controller keeps running: " + said);
                assertTrue(!said.contains("connected to the middleware"), said);
            } finally {
                stranger.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }

            Path trustedOut = dir.resolve("controller.txt");
            Process c = controller(java, trustedOut, "--world", world, "--port", String.valueOf(port),
                    "--secret-file", secret.toString(), "--seconds", "600",
                    "--tls-store", dir.resolve("middleware-trust.p12").toString(), "--tls-password-file", password.toString());
            try {
                String said = awaitOutput(c, trustedOut, s -> s.contains("connected to the middleware at 127.0.0.1:" + port));
                assertTrue(said.contains("over TLS"), said);
                awaitOutput(agent, agentOut, s -> s.contains("Acquiring data"));
            } finally {
                c.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        } finally {
            agent.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    private static Process controller(String java, Path out, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "jacabot.app.cli.JacabotCommand", "controller"));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.toFile()).start();
    }

    /**
     * {@return the process's output once it satisfies {@code shows}; fails if the process ends first}
     * Waits up to 240 s: at load 40 an untrusting controller once reported nothing within 120 s.
     */
    private static String awaitOutput(Process p, Path out, Predicate<String> shows) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
        String said = Files.readString(out);
        while (!shows.test(said) && System.nanoTime() < end) {
            assertTrue(p.isAlive(), "ended before saying it: " + said);
            Thread.sleep(50);
            said = Files.readString(out);
        }
        assertTrue(shows.test(said), "not said within 240 s: " + said);
        return said;
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
