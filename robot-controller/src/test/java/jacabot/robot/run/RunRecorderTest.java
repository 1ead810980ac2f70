package jacabot.robot.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.device.Gripper;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.robot.Robot;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The recorder's figures on scripted runs: the robot is driven by hand, step by step. */
class RunRecorderTest {
    /** A noiseless 1 m arena with a Khepera "k" at (x, 0) heading north, plus other members. */
    private static SimWorld khepera(double x, String members) throws WorldFileException {
        return SimWorld.parse("{ \"arena\": {\"width\": 1.0, \"depth\": 1.0}, \"seed\": 7, \"sensorNoise\": false,"
                + " \"robots\": [{\"name\": \"k\", \"model\": \"khepera\", \"x\": " + x + ", \"z\": 0, \"heading\": 0}]"
                + (members.isEmpty() ? "" : ", " + members) + " }", "test");
    }

    private static void run(SimWorld w, double seconds) {
        for (long n = Math.round(seconds * 1000 / w.controlStep()); n > 0; n--) {
            w.step();
        }
    }

    /** Lowers the arm and closes the fingers on the cylinder in front, then lifts it. */
    private static void grasp(SimWorld w, Gripper g) {
        g.armDown();
        run(w, 1.0);
        g.closeGrip();
        run(w, 0.6);
        g.armUp();
        run(w, 1.0);
    }

    @Test
    void drivingIntoAWallGivesSustainedContact() throws WorldFileException {
        SimWorld w = khepera(0.41, "");
        RunRecorder rec = RunRecorder.attach(w, "k");
        w.robot("k").setSpeeds(100, 100);
        run(w, 10);
        RunSummary s = rec.summary("script");
        // 5 cm/s: the wall (x = 0.5) is 6 cm ahead of the rim, so about 8.8 s of the 10 are pressing on it.
        assertTrue(s.contactTime() > 8 && s.contactTime() < 9, "contact " + s.contactTime());
        assertEquals(s.contactTime(), s.longestContact(), 0.05);
        assertEquals(0.5 - 0.41 - 0.0285, s.distance(), 0.005);
        assertEquals(10.0, s.duration(), 1e-9);
        assertEquals(100, s.cells());
        // x stays in 0.4..0.5; z = 0 is the line between two rows of cells, so one or both count.
        assertTrue(s.cellsVisited() >= 1 && s.cellsVisited() <= 2, "cells " + s.cellsVisited());
        assertEquals(s.cellsVisited() / 100.0, s.coverage(), 1e-9);
        assertTrue(s.events().isEmpty(), "a contact still going on is not logged: " + s.events());
    }

    @Test
    void aContactThatEndsIsLoggedWithItsLength() throws WorldFileException {
        SimWorld w = khepera(0.40, "");
        RunRecorder rec = RunRecorder.attach(w, "k");
        Robot k = w.robot("k");
        k.setSpeeds(100, 100);
        run(w, 4);
        k.setSpeeds(-100, -100);
        run(w, 1);
        RunSummary s = rec.summary("script");
        assertEquals(1, s.events().size(), s.events().toString());
        assertTrue(s.events().get(0).matches("t=4\\.0[0-9]{2} contact for 2\\.[0-9]{3} s"), s.events().get(0));
        assertEquals(s.contactTime(), s.longestContact(), 1e-9);
    }

    @Test
    void aCylinderCarriedIntoTheStorageAreaAndReleasedIsOneDelivery() throws WorldFileException {
        SimWorld w = khepera(0.0, "\"cylinders\": [{\"id\": \"c1\", \"x\": 0.056, \"z\": 0}],"
                + " \"storage\": {\"x\": 0.3, \"z\": 0, \"radius\": 0.06}");
        RunRecorder rec = RunRecorder.attach(w, "k");
        Robot k = w.robot("k");
        Gripper g = k.getGripper();
        grasp(w, g);
        k.setSpeeds(50, 50);
        while (k.pose().x() < 0.25) {
            w.step();
        }
        k.setSpeeds(0, 0);
        g.openGrip();
        run(w, 1);
        RunSummary s = rec.summary("script");
        assertEquals(1, s.picks());
        assertEquals(1, s.deliveries());
        assertEquals(0, s.lost());
        assertEquals(1, s.storageEntriesWithCylinder());
        assertEquals(0, s.storageEntriesEmpty());
        assertTrue(s.deliveryTimes().get(0) > s.pickTimes().get(0));
        assertTrue(s.eventLog().contains(" picked cylinder c1\n"), s.eventLog());
        assertTrue(s.eventLog().matches("(?s).*t=[0-9.]+ delivered cylinder c1 at \\(0\\.3[0-9]{2}, 0\\.000\\)\n.*"), s.eventLog());
        assertTrue(s.eventLog().contains(" entered storage area with cylinder c1\n"), s.eventLog());
    }

    @Test
    void comingBackIntoTheStorageAreaEmptyIsFlagged() throws WorldFileException {
        SimWorld w = khepera(0.0, "\"storage\": {\"x\": 0.3, \"z\": 0, \"radius\": 0.06}");
        RunRecorder rec = RunRecorder.attach(w, "k");
        Robot k = w.robot("k");
        k.setSpeeds(50, 50);
        while (k.pose().x() < 0.28) {
            w.step();
        }
        k.setSpeeds(-50, -50);
        while (k.pose().x() > 0.1) {
            w.step();
        }
        k.setSpeeds(50, 50);
        while (k.pose().x() < 0.26) {
            w.step();
        }
        RunSummary s = rec.summary("script");
        assertEquals(2, s.storageEntriesEmpty());
        assertEquals(0, s.storageEntriesWithCylinder());
        assertEquals(3, s.events().size(), s.events().toString());
        assertTrue(s.events().get(0).endsWith(" entered storage area without a cylinder"));
        assertTrue(s.events().get(1).endsWith(" left storage area"));
    }

    @Test
    void aCylinderSetDownOutsideTheAreaOrKnockedOutIsNoDelivery() throws WorldFileException {
        SimWorld w = khepera(0.0, "\"cylinders\": [{\"id\": \"c1\", \"x\": 0.056, \"z\": 0}],"
                + " \"storage\": {\"x\": 0.3, \"z\": 0.3, \"radius\": 0.06}");
        RunRecorder rec = RunRecorder.attach(w, "k");
        Robot k = w.robot("k");
        Gripper g = k.getGripper();
        grasp(w, g);
        g.openGrip();
        run(w, 1);
        grasp(w, g);
        w.supervisor().knockCarried("k");
        run(w, 0.2);
        RunSummary s = rec.summary("script");
        assertEquals(2, s.picks());
        assertEquals(0, s.deliveries());
        assertEquals(1, s.lost());
        assertTrue(s.eventLog().contains(" set down cylinder c1 outside the storage area at (0.050, 0.000)\n"), s.eventLog());
        assertTrue(s.eventLog().contains(" world: robot 'k' lost 'c1'\n"), s.eventLog());
        assertTrue(s.eventLog().matches("(?s).* lost cylinder c1 at \\(.*"), s.eventLog());
    }

    @Test
    void batteryChargerAndEmptyBattery() throws WorldFileException {
        SimWorld w = khepera(0.0, "\"charger\": {\"x\": 0.2, \"z\": 0, \"radius\": 0.06, \"power\": 20}");
        RunRecorder rec = RunRecorder.attach(w, "k");
        Robot k = w.robot("k");
        k.setSpeeds(50, 50);
        while (k.pose().x() < 0.2) {
            w.step();
        }
        k.setSpeeds(0, 0);
        run(w, 5);
        double charged = k.getBattery().energy();
        k.setSpeeds(50, 50);
        while (k.pose().x() < 0.3) {
            w.step();
        }
        w.supervisor().setBattery("k", 0);
        run(w, 0.1);
        RunSummary s = rec.summary("script");
        assertEquals(1, s.chargerVisits());
        assertTrue(s.recharged() > 0, "recharged " + s.recharged());
        assertTrue(s.batteryEmptied());
        assertEquals(0.0, s.batteryMin(), 1e-9);
        assertTrue(s.eventLog().contains(" reached charger ("), s.eventLog());
        assertTrue(s.eventLog().contains(" battery empty\n"), s.eventLog());
        assertTrue(charged > 999, "a full battery stays full on the charger: " + charged);
    }

    @Test
    void aRobotWithoutBatteryHasNoBatteryFigures() throws WorldFileException {
        SimWorld w = SimWorld.parse("{ \"robots\": [{\"name\": \"m\", \"model\": \"mybot\"}] }", "test");
        RunRecorder rec = RunRecorder.attach(w, "m");
        run(w, 1);
        RunSummary s = rec.summary("script");
        assertNull(s.batteryMin());
        assertFalse(s.batteryEmptied());
        assertFalse(s.toText().contains("battery"), s.toText());
        assertTrue(s.toJson().contains("\"batteryMin\" : null"), s.toJson());
    }

    @Test
    void summariesGoToJsonAndBackAndToText(@TempDir Path dir) throws Exception {
        SimWorld w = khepera(0.0, "\"cylinders\": [{\"id\": \"c1\", \"x\": 0.056, \"z\": 0}]");
        RunRecorder rec = RunRecorder.attach(w, "k");
        grasp(w, w.robot("k").getGripper());
        rec.note("picking done");
        RunSummary s = rec.summary("script");
        assertEquals(s, RunSummary.fromJson(s.toJson()));
        assertTrue(s.toJson().startsWith("{\n  \"world\" : \"test\",\n  \"robot\" : \"k\",\n  \"controller\" : \"script\","),
                s.toJson());
        assertTrue(s.events().get(s.events().size() - 1).endsWith(" controller: picking done"), s.events().toString());
        assertTrue(s.toText().contains("cylinders: 1 picked (at "), s.toText());
        Path json = dir.resolve("run.json");
        s.writeJson(json);
        assertEquals(s, RunSummary.fromJson(Files.readString(json)));
        System.setProperty("java.awt.headless", "true");
        Path png = dir.resolve("run.png");
        rec.writePng(png, 200, 220);
        assertTrue(Files.size(png) > 100);
    }
}
