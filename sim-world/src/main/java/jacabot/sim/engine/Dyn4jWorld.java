package jacabot.sim.engine;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.dyn4j.collision.CollisionItem;
import org.dyn4j.collision.CollisionPair;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.dynamics.ContinuousDetectionMode;
import org.dyn4j.dynamics.contact.Contact;
import org.dyn4j.dynamics.contact.ContactConstraint;
import org.dyn4j.dynamics.contact.SolvedContact;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.World;
import org.dyn4j.world.WorldCollisionData;
import org.dyn4j.world.listener.ContactListener;

/**
 * dyn4j's world, whose time-of-impact pass drops first the pairs that cannot meet within the step.
 *
 * <p>At every physics step dyn4j walks every pair of its continuous broad phase (a fixed body and a
 * moving one whose grown boxes once overlapped, {@link BroadPhases}), keeps or drops it from that
 * list, then asks five questions of each pair (two of them lookups in its constraint graph) before it
 * groups the pairs by moving body and asks the time-of-impact detector about each. Most pairs are
 * centimetres apart and move a millimetre a step: the detector's own test
 * ({@link BoundedAdvancement#cannotMeet}) answers {@code false} for them. Here that test comes
 * first, on the inputs dyn4j gives the detector (the bodies' previous transforms and their motion in
 * the step), and a pair it clears is not grouped: in dyn4j its every fixture pair would get
 * {@code false}, which changes nothing. The list is kept exactly as dyn4j keeps it, the other pairs
 * are grouped as dyn4j groups them and solved by dyn4j's own per-body step. Each group's solution
 * moves only its body (the other bodies of its pairs are fixed), so the groups' order does not
 * matter. With time-of-impact listeners, another detector or another mode, dyn4j's own pass runs.
 * {@code BroadPhasesTest} steps worlds with impacts both ways and compares every body at every step.
 * The pairs it keeps are {@link ClearancePair}s, which skip the test while the clearance they last
 * measured, less both bodies' motion since, still exceeds what the step can close.
 *
 * <p>Its step is dyn4j's ({@code AbstractPhysicsWorld.step}, line for line) but for the island solve,
 * which marks the bodies instead of filling hash sets ({@link Islands}).
 */
final class Dyn4jWorld extends World<Body> {
    private final Islands islands = new Islands();
    private long impacts;

    /** Takes a {@link TrackedBody} only: {@link Islands} and {@link BroadPhases} keep their marks and entries on it. */
    @Override
    public void addBody(Body body) {
        if (!(body instanceof TrackedBody)) {
            throw new IllegalArgumentException("a body of this world is a TrackedBody, not a " + body.getClass().getSimpleName());
        }
        super.addBody(body);
        ((TrackedBody) body).graphNode = constraintGraph.getNode(body);
        ((TrackedBody) body).joined();
    }

    /** Collision data whose penetration remembers the pair's clearance for {@link BoundedGjk}. */
    @Override
    protected WorldCollisionData<Body> createCollisionData(CollisionPair<CollisionItem<Body, BodyFixture>> pair) {
        return new ClearancePenetration.Data(pair);
    }

    @Override
    protected void step() {
        int listeners = stepListeners.size();
        for (int i = 0; i < listeners; i++) {
            stepListeners.get(i).begin(timeStep, this);
        }
        if (updateRequired) {
            countMotion(); // whatever moved the bodies since the last step (teleports), before this detection reads them
            detect();
            for (int i = 0; i < listeners; i++) {
                stepListeners.get(i).updatePerformed(timeStep, this);
            }
            updateRequired = false;
        }
        if (!contactListeners.isEmpty()) {
            for (WorldCollisionData<Body> data : contactCollisions) {
                ContactConstraint<Body> cc = data.getContactConstraint();
                for (Contact contact : cc.getContacts()) {
                    for (ContactListener<Body> listener : contactListeners) {
                        listener.preSolve(data, contact);
                    }
                }
            }
        }
        ContinuousDetectionMode mode = settings.getContinuousDetectionMode();
        for (int i = 0, n = bodies.size(); i < n; i++) {
            Body body = bodies.get(i);
            if (!((TrackedBody) body).fixed) {
                ((TrackedBody) body).countMotion(); // what moved it since the step's last count, in the walk that reads it anyway
            }
            body.getPreviousTransform().set(body.getTransform());
        }
        if (!islands.solve(bodies, !joints.isEmpty(), constraintGraph, contactConstraintSolver, gravity, timeStep, settings)) {
            constraintGraph.solve(contactConstraintSolver, gravity, timeStep, settings);
        }
        if (!contactListeners.isEmpty()) {
            for (WorldCollisionData<Body> data : contactCollisions) {
                ContactConstraint<Body> cc = data.getContactConstraint();
                for (SolvedContact contact : cc.getContacts()) {
                    for (ContactListener<Body> listener : contactListeners) {
                        listener.postSolve(data, contact);
                    }
                }
            }
        }
        for (int i = 0; i < listeners; i++) {
            stepListeners.get(i).postSolve(timeStep, this);
        }
        if (mode != ContinuousDetectionMode.NONE) {
            ccdBroadphase.update();
            solveTOI(mode);
            ccdBroadphase.clearUpdates();
        }
        countMotion(); // the solve's and the time-of-impact pass's
        detect();
        updateRequired = false;
        for (int i = 0; i < listeners; i++) {
            stepListeners.get(i).end(timeStep, this);
        }
    }

    @Override
    protected boolean solveTOI(ContinuousDetectionMode mode) {
        if (mode != ContinuousDetectionMode.ALL || !timeOfImpactListeners.isEmpty()
                || !(getTimeOfImpactDetector() instanceof BoundedAdvancement)) {
            return super.solveTOI(mode);
        }
        Iterator<CollisionPair<Body>> found = ccdBroadphase.detectIterator();
        while (found.hasNext()) {
            CollisionPair<Body> next = found.next(); // the broad phase reuses its pair object: copied
            ccdCollisionData.add(new ClearancePair(next.getFirst(), next.getSecond()));
        }
        double dt = timeStep.getDeltaTime();
        Map<Body, List<Body>> groups = null;
        for (Iterator<CollisionPair<Body>> it = ccdCollisionData.iterator(); it.hasNext(); ) {
            CollisionPair<Body> pair = it.next();
            Body body1 = pair.getFirst(), body2 = pair.getSecond();
            if (!ccdBroadphase.contains(body1) || !ccdBroadphase.contains(body2)) {
                it.remove();
                continue;
            }
            if ((ccdBroadphase.isUpdated(body1) || ccdBroadphase.isUpdated(body2)) && !ccdBroadphase.detect(body1, body2)) {
                it.remove();
                continue;
            }
            Body mover = body1.isDynamic() ? body1 : body2.isDynamic() ? body2 : null;
            if (mover == null) {
                continue; // two fixed bodies: dyn4j skips them below
            }
            Body other = mover == body1 ? body2 : body1;
            if (pair instanceof ClearancePair remembered && mover.getFixtureCount() == 1 && other.getFixtureCount() == 1
                    ? remembered.cannotMeet((TrackedBody) mover, (TrackedBody) other, dt) : cannotMeet(mover, other, dt)) {
                continue;
            }
            // dyn4j's questions, in its order
            if (!body1.isEnabled() || !body2.isEnabled()) {
                continue;
            }
            if (body1.isDynamic() && body2.isDynamic() && !body1.isBullet() && !body2.isBullet()) {
                continue;
            }
            if (body1.getMass().isInfinite() && body2.getMass().isInfinite()) {
                continue;
            }
            if (body1.isAtRest() && body2.isAtRest()) {
                continue;
            }
            if (!isJointCollisionAllowed(body1, body2) || isInContact(body1, body2)) {
                continue;
            }
            if (groups == null) {
                groups = new LinkedHashMap<>();
            }
            groups.computeIfAbsent(mover, b -> new ArrayList<>()).add(other);
        }
        boolean solved = false;
        if (groups != null) {
            for (Map.Entry<Body, List<Body>> g : groups.entrySet()) {
                if (solveTOI(g.getKey(), g.getValue(), timeOfImpactListeners)) {
                    solved = true;
                    impacts++;
                }
            }
        }
        return solved;
    }

    /**
     * {@return whether the detector answers {@code false} for every fixture pair of the two bodies in
     * this step} The motion is formed as dyn4j forms it for the detector ({@code velocity.product(dt)}).
     */
    static boolean cannotMeet(Body mover, Body other, double dt) {
        Vector2 v1 = mover.getLinearVelocity(), v2 = other.getLinearVelocity();
        double dp1x = v1.x * dt, dp1y = v1.y * dt, dp2x = v2.x * dt, dp2y = v2.y * dt;
        double da1 = mover.getAngularVelocity() * dt, da2 = other.getAngularVelocity() * dt;
        Transform tx1 = mover.getPreviousTransform(), tx2 = other.getPreviousTransform();
        for (int k = 0, n2 = other.getFixtureCount(); k < n2; k++) {
            BodyFixture f2 = other.getFixture(k);
            for (int j = 0, n1 = mover.getFixtureCount(); j < n1; j++) {
                BodyFixture f1 = mover.getFixture(j);
                if (!BoundedAdvancement.cannotMeet(f1.getShape(), tx1, dp1x, dp1y, da1, f2.getShape(), tx2, dp2x, dp2y, da2, 0.0, 1.0)) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * Advances every body's odometer by its motion since it last counted: before a detection the step
     * begins with (what moved the bodies between steps; otherwise the walk that keeps the previous
     * transforms counts it) and before the step's last detection (the step's own motion),
     * so that every transform the detections and the time-of-impact pass read is one the odometers
     * counted ({@link RememberedClearance}). A fixed body counts its teleports itself ({@link TrackedBody#fixed}).
     */
    private void countMotion() {
        for (int i = 0, n = bodies.size(); i < n; i++) {
            TrackedBody body = (TrackedBody) bodies.get(i);
            if (!body.fixed) {
                body.countMotion();
            }
        }
    }

    /** {@return how many physics steps {@link Islands} solved (the others, dyn4j's own walk)} */
    long islandSteps() {
        return islands.steps();
    }

    /** {@return how many moving bodies the time-of-impact pass moved back so far} */
    long impacts() {
        return impacts;
    }
}
