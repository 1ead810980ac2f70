package jacabot.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.World;
import org.junit.jupiter.api.Test;

class Dyn4jWiringTest {
    @Test
    void aTopDownWorldStepsABodyAtConstantVelocity() {
        World<Body> world = new World<>();
        world.setGravity(World.ZERO_GRAVITY);
        world.getSettings().setStepFrequency(0.008);
        Body body = new Body();
        body.addFixture(Geometry.createCircle(0.05));
        body.setMass(MassType.NORMAL);
        body.setLinearVelocity(new Vector2(1.0, 0.0));
        body.setLinearDamping(0);
        world.addBody(body);
        world.step(125);
        assertEquals(1.0, body.getTransform().getTranslationX(), 1e-9);
        assertEquals(0.0, body.getTransform().getTranslationY(), 1e-9);
    }
}
