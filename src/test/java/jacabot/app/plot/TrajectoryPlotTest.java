package jacabot.app.plot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** {@code trajectory.png} has a legend under the world: an entry for what the world holds, each in its colour. */
class TrajectoryPlotTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void aLegendUnderTheWorldInTheWorldsColours() throws Exception {
        WorldSnapshot s = SimWorld.load(ROOT.resolve("worlds/suspend-resume.json")).snapshot();
        var entries = TrajectoryPlot.entries(s);
        assertTrue(entries.containsKey("path"), entries.keySet().toString());
        assertTrue(entries.containsKey("storage area") && entries.containsKey("charger"), entries.keySet().toString());
        assertTrue(entries.keySet().stream().anyMatch(k -> k.startsWith("cylinder")), entries.keySet().toString());
        BufferedImage img = TrajectoryPlot.draw(s, 600);
        assertEquals(600 + TrajectoryPlot.LEGEND, img.getHeight());
        // the first swatch is the robot's, in its colour, under the world
        var robot = s.robots().get(0).color();
        assertEquals(new Color(robot.red(), robot.green(), robot.blue()).getRGB(), img.getRGB(16, 600 + 12));
        assertEquals(new Color(30, 30, 36).getRGB(), img.getRGB(5, 600 + 2), "the legend's own strip");
    }
}
