package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The handshake's proofs, the secret file, the reading checks and the stream bounds, without sockets. */
class LinkSecurityTest {
    /** Both ends of a handshake over pipes; {@return the controller's and the middleware's outcome} */
    private static Object[] shake(LinkSecret controllerKey, LinkSecret middlewareKey) throws Exception {
        var toMiddleware = new PipedOutputStream();
        var middlewareIn = new PipedInputStream(toMiddleware, 4096);
        var toController = new PipedOutputStream();
        var controllerIn = new PipedInputStream(toController, 4096);
        var hello = new Protocol.Hello(Protocol.VERSION, "khepera", "navigation", 40, false,
                List.of(SensorKind.GPS.id()));
        var middleware = CompletableFuture.supplyAsync(() -> {
            try {
                return (Object) Handshake.asMiddleware(new DataInputStream(middlewareIn), new DataOutputStream(toController),
                        middlewareKey);
            } catch (IOException e) {
                return e;
            } finally {
                try {
                    toController.close();
                } catch (IOException e) {
                    // closing
                }
            }
        });
        Object controller;
        try {
            controller = Handshake.asController(new DataInputStream(controllerIn), new DataOutputStream(toMiddleware), hello,
                    controllerKey);
        } catch (IOException e) {
            controller = e;
        } finally {
            toMiddleware.close();
        }
        return new Object[] {controller, middleware.get(10, TimeUnit.SECONDS)};
    }

    @Test
    void onlyTheSameSecretOpensASession() throws Exception {
        LinkSecret k = LinkSecret.random();
        Object[] ok = shake(k, k);
        assertTrue(ok[0] instanceof Protocol.Welcome w && w.accepted(), String.valueOf(ok[0]));
        assertTrue(ok[1] instanceof Protocol.Hello h && h.sensors().equals(List.of(SensorKind.GPS.id())), String.valueOf(ok[1]));

        Object[] wrong = shake(LinkSecret.random(), k);
        assertTrue(wrong[0] instanceof AuthenticationException e && e.getMessage().startsWith("the middleware cannot prove"),
                String.valueOf(wrong[0]));
        assertTrue(wrong[1] instanceof IOException, "the middleware never opened a session: " + wrong[1]);
    }

    @Test
    void aForgedProofIsRefused() throws Exception {
        // what an intruder without the key can do: greet, ignore the middleware's proof, answer zeros
        LinkSecret k = LinkSecret.random();
        var bytes = new ByteArrayOutputStream();
        var hello = new Protocol.Hello(Protocol.VERSION, "x", "y", 40, false);
        bytes.write(hello.bytes());
        bytes.write(new byte[Handshake.NONCE_BYTES]);
        bytes.write(new byte[Handshake.MAC_BYTES]);
        var e = assertThrows(AuthenticationException.class, () -> Handshake.asMiddleware(
                new DataInputStream(new ByteArrayInputStream(bytes.toByteArray())),
                new DataOutputStream(new ByteArrayOutputStream()), k));
        assertEquals("the controller could not prove the link secret", e.getMessage());
    }

    @Test
    void theSecretFileIsMadeForItsOwnerOnlyAndRefusedWhenOthersMayReadIt(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("sub/link-secret");
        LinkSecret made = LinkSecret.loadOrCreate(file);
        assertEquals(PosixFilePermissions.fromString("rw-------"), Files.getPosixFilePermissions(file));
        assertEquals(PosixFilePermissions.fromString("rwx------"), Files.getPosixFilePermissions(file.getParent()));
        assertEquals(made.toHex(), LinkSecret.loadOrCreate(file).toHex(), "read back, not made again");
        assertFalse(made.toString().contains(made.toHex()), "toString never shows the key");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        var e = assertThrows(IOException.class, () -> LinkSecret.load(file));
        assertTrue(e.getMessage().contains("chmod 600"), e.getMessage());
        Files.setPosixFilePermissions(file, EnumSet.of(PosixFilePermission.OWNER_READ));
        Files.writeString(dir.resolve("bad"), "not hex");
        Files.setPosixFilePermissions(dir.resolve("bad"), PosixFilePermissions.fromString("rw-------"));
        assertTrue(assertThrows(IOException.class, () -> LinkSecret.load(dir.resolve("bad"))).getMessage()
                .contains("not a link secret"));
    }

    /**
     * The agent platform and the controller start together and both find no secret file: each makes
     * one, and both must end with the same secret, never reading a file made but not yet written
     * (readers do not wait: the file appears whole or not at all). Four makers at once, 40 times.
     */
    @Test
    void aSecretFileReadWhileItIsWrittenGivesTheSecret(@TempDir Path dir) throws Exception {
        var pool = Executors.newFixedThreadPool(4);
        try {
            for (int round = 0; round < 40; round++) {
                Path file = dir.resolve("round-" + round).resolve("link-secret");
                var start = new CountDownLatch(1);
                List<Future<String>> sides = new ArrayList<>();
                for (int side = 0; side < 4; side++) {
                    sides.add(pool.submit(() -> {
                        start.await();
                        return LinkSecret.loadOrCreate(file).toHex();
                    }));
                }
                start.countDown();
                String first = sides.get(0).get(10, TimeUnit.SECONDS); // a partial file would throw "not a link secret"
                for (var side : sides) {
                    assertEquals(first, side.get(10, TimeUnit.SECONDS), "round " + round + ": every side has the same secret");
                }
                assertEquals(first, Files.readString(file).trim(), "the file holds that secret");
                assertEquals(PosixFilePermissions.fromString("rw-------"), Files.getPosixFilePermissions(file));
                try (var left = Files.list(file.getParent())) {
                    assertEquals(List.of(file), left.toList(), "no temporary file left beside it");
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void readingsAreCheckedAgainstTheDeclaredDevices() {
        var check = new ReadingCheck(List.of(SensorKind.LEFT_DISTANCE.id(), SensorKind.GRIPPER_POSITIONS.id(),
                SensorKind.CAMERA_SECTIONS.id(), SensorKind.GPS.id(), SensorKind.CAMERA_IMAGE.id()));
        assertNull(check.problem(new SensorInfo(SensorKind.LEFT_DISTANCE.id(), 12.5)));
        assertNull(check.problem(new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[] {0, 1})));
        assertNull(check.problem(new SensorInfo(SensorKind.GPS.id(), 1, 0, -1)));
        assertNull(check.problem(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[] {2, 1, 0, 0})));
        assertTrue(check.problem(new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[0])).contains("expected 2"));
        assertTrue(check.problem(new SensorInfo(SensorKind.BATTERY.id(), 1)).contains("not declared"));
        assertTrue(check.problem(new SensorInfo(SensorKind.LEFT_DISTANCE.id(), Double.NaN)).contains("not finite"));
        assertTrue(check.problem(new SensorInfo(SensorKind.GPS.id(), 3.0)).contains("carries other fields"));
        assertTrue(check.problem(new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), new int[9 + 1])).contains("expected 9"));
        assertTrue(check.problem(new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), new int[] {0, 0, 0, 0, 300, 0, 0, 0, 0}))
                .contains("outside 0..255"));
        assertTrue(check.problem(new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[] {3, 3, 0})).contains("width x height"));
        assertTrue(check.problem(new SensorInfo(99, 1)).contains("not declared"));
    }

    @Test
    void theStreamRestartsAndARestartlessOrOversizedStreamIsRefused() throws Exception {
        var bytes = new ByteArrayOutputStream();
        var w = new SensorDataWriter(bytes, 2); // a restart every 2 batches
        for (int i = 0; i < 9; i++) {
            w.writeStep(new Uplink.Batch(i, 40L * i, 0, List.of(new SensorInfo(SensorKind.LEFT_DISTANCE.id(), i))),
                    new Uplink.StepMarker(i, 40L * i, false));
        }
        var limits = new SensorInfoFilter.Limits(1000, 3, 1000, 10_000, 20_000, 3);
        var r = new SensorDataReader(new ByteArrayInputStream(bytes.toByteArray()), limits);
        int batches = 0;
        for (Uplink f = r.read(); f != null; f = r.read()) {
            if (f instanceof Uplink.Batch b) {
                assertEquals(batches, (long) b.readings().get(0).getVal());
                batches++;
            }
        }
        assertEquals(9, batches, "3 objects per stream allowed, the writer restarts every 2 batches");

        var raw = new ByteArrayOutputStream();
        var out = new ObjectOutputStream(raw);
        for (int i = 0; i < 5; i++) { // never restarts
            out.writeByte(Uplink.BATCH);
            out.writeLong(i);
            out.writeLong(0);
            out.writeLong(0);
            out.writeInt(1);
            SensorInfoCodec.write(out, new SensorInfo(SensorKind.LEFT_DISTANCE.id(), i));
        }
        out.flush();
        var never = new SensorDataReader(new ByteArrayInputStream(raw.toByteArray()), limits);
        var e = assertThrows(ProtocolException.class, () -> {
            while (never.read() != null) {
                // until refused
            }
        });
        assertTrue(e.getMessage().contains("more than 3 readings without a stream restart"), e.getMessage());
        assertEquals(0, never.frameStartNanos(), "no frame in progress after the refusal is reported");
    }
}
