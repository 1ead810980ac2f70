package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.experiments.CylinderSighting;
import jacabot.sim.SimWorld;
import jacabot.sim.device.Camera;
import jacabot.sim.io.WorldFileException;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * A team's robots through the middleware's eyes (thesis Chapter 6): the far sight that finds red
 * cylinders in the camera image never takes another Khepera for one.
 */
class TeamSightTest {
    private static Optional<CylinderSighting> sight(String cylinders) throws WorldFileException {
        SimWorld w = SimWorld.parse("{ \"arena\": {\"width\": 1.0, \"depth\": 1.0}, \"seed\": 3, " + cylinders
                + "\"robots\": [{\"name\": \"a\", \"model\": \"khepera\", \"x\": 0, \"z\": 0, \"heading\": 0},"
                + " {\"name\": \"b\", \"model\": \"khepera\", \"x\": 0.25, \"z\": 0, \"heading\": 90}] }", "team");
        Camera cam = w.robot("a").getCamera("camera");
        cam.enable(w.controlStep());
        w.step();
        int[] image = cam.getImage();
        int[] framed = new int[image.length + 2]; // as the controller sends it: width, height, pixels
        framed[0] = cam.getWidth();
        framed[1] = cam.getHeight();
        System.arraycopy(image, 0, framed, 2, image.length);
        return CylinderSighting.find(framed, cam.getFov());
    }

    @Test
    void aRobotAheadIsNoCylinder() throws WorldFileException {
        assertTrue(sight("").isEmpty(), "robot b straight ahead is not sighted as a cylinder");
    }

    @Test
    void aCylinderBesideARobotIsSightedWhereItStands() throws WorldFileException {
        CylinderSighting s = sight("\"cylinders\": [{\"id\": \"red1\", \"x\": 0.3, \"z\": 0.12}], ").orElseThrow();
        double bearing = Math.toDegrees(Math.atan2(0.12, 0.3 - 0.0285)); // from the lens at the front rim
        assertTrue(Math.abs(s.offset() - bearing) < 2, "sighted at " + s.offset() + "°, stands at " + bearing + "°");
    }
}
