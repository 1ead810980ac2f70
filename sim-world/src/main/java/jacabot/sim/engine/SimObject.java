package jacabot.sim.engine;

import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Transform;

/** One thing of the world and its dyn4j body. Internal. */
final class SimObject {
    final String id;
    final ObjectKind kind;
    final Body body;
    final Rgb color;
    final double height;
    final double sizeX, sizeZ; // full sizes; a cylinder's diameter twice
    final boolean movable;
    String carriedBy; // the robot holding this cylinder, or null
    private AABB bounds; // cached for the sensors' rays, with the transform it was computed at
    private double boundsX, boundsY, boundsCos, boundsSin;

    SimObject(String id, ObjectKind kind, Body body, Rgb color, double height, double sizeX, double sizeZ, boolean movable) {
        this.id = id;
        this.kind = kind;
        this.body = body;
        this.color = color;
        this.height = height;
        this.sizeX = sizeX;
        this.sizeZ = sizeZ;
        this.movable = movable;
        body.setUserData(this);
    }

    /** {@return the body's bounding box, recomputed only when the body has moved since the last call} */
    AABB bounds() {
        Transform t = body.getTransform();
        if (bounds == null || t.getTranslationX() != boundsX || t.getTranslationY() != boundsY || t.getCost() != boundsCos
                || t.getSint() != boundsSin) {
            bounds = body.createAABB();
            boundsX = t.getTranslationX();
            boundsY = t.getTranslationY();
            boundsCos = t.getCost();
            boundsSin = t.getSint();
        }
        return bounds;
    }

    Pose pose() {
        return new Pose(body.getTransform().getTranslationX(), body.getTransform().getTranslationY(),
                Math.toDegrees(body.getTransform().getRotationAngle()));
    }

    /** Teleports the body and stops it. */
    void place(double x, double z, double heading) {
        body.getTransform().setTranslation(x, z);
        body.getTransform().setRotation(Math.toRadians(heading));
        body.setLinearVelocity(0, 0);
        body.setAngularVelocity(0);
    }

    /** Makes the body a ghost (no collision response) or solid again. */
    void setGhost(boolean ghost) {
        for (BodyFixture f : body.getFixtures()) {
            f.setSensor(ghost);
        }
    }

    double radius() {
        return sizeX / 2;
    }
}
