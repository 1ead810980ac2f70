package jacabot.sim.engine;

import jacabot.sim.device.RayHit;
import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Convex;

/** One thing of the world and its dyn4j body. Internal. */
final class SimObject {
    final String id;
    final ObjectKind kind;
    final Body body;
    final Rgb color;
    /** The share of infra-red light the surface returns, what the distance sensors read it by. */
    final double reflectance;
    final double height;
    final double sizeX, sizeZ; // full sizes; a cylinder's diameter twice
    final boolean movable;
    String carriedBy; // the robot holding this cylinder, or null
    /** The body's one shape, a circle or a rectangle centred on the body, which the sensors' rays solve in closed form. */
    final Convex shape;
    /** The radius of the circle around the body's centre that holds the shape, for the rays' broad phase. */
    final double boundingRadius;

    /** A painted object: its infra-red reflectance follows its colour ({@link RayHit#reflectanceOf}). */
    SimObject(String id, ObjectKind kind, Body body, Rgb color, double height, double sizeX, double sizeZ, boolean movable) {
        this(id, kind, body, color, RayHit.reflectanceOf(color), height, sizeX, sizeZ, movable);
    }

    SimObject(String id, ObjectKind kind, Body body, Rgb color, double reflectance, double height, double sizeX, double sizeZ,
              boolean movable) {
        this.id = id;
        this.kind = kind;
        this.body = body;
        this.color = color;
        this.reflectance = reflectance;
        this.height = height;
        this.sizeX = sizeX;
        this.sizeZ = sizeZ;
        this.movable = movable;
        this.shape = body.getFixture(0).getShape();
        this.boundingRadius = shape.getRadius();
        body.setUserData(this);
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
        if (body instanceof TrackedBody t) {
            t.teleported();
        }
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
