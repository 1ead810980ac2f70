package jacabot.sim.engine;

import jacabot.sim.device.RayHit;
import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;

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

    /**
     * The body's pose. A robot's sensors each ask for it after every physics step in which they read
     * (six times a control step for the camera and five distance sensors), and the heading is an arc
     * cosine: the last pose is kept with the transform's bits it was made from, and given again
     * while they are the same. The pose is a function of those bits, so it is the one made anew.
     */
    Pose pose() {
        Transform t = body.getTransform();
        double x = t.getTranslationX(), z = t.getTranslationY(), cos = t.getCost(), sin = t.getSint();
        PoseMade last = lastPose; // read once: a view thread may ask too, and each PoseMade is whole
        if (last != null && last.madeFrom(x, z, cos, sin)) {
            return last.pose;
        }
        Pose p = new Pose(x, z, Math.toDegrees(t.getRotationAngle()));
        lastPose = new PoseMade(bits(x), bits(z), bits(cos), bits(sin), p);
        return p;
    }

    private PoseMade lastPose;

    /** A pose and the bits of the transform it was made from (translation, cosine, sine). */
    private record PoseMade(long x, long z, long cos, long sin, Pose pose) {
        boolean madeFrom(double x, double z, double cos, double sin) {
            return this.x == bits(x) && this.z == bits(z) && this.cos == bits(cos) && this.sin == bits(sin);
        }
    }

    private static long bits(double v) {
        return Double.doubleToRawLongBits(v);
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
