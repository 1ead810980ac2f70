package jacabot.sim.engine;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.dyn4j.collision.CollisionPair;
import org.dyn4j.collision.broadphase.AABBExpansionMethod;
import org.dyn4j.collision.broadphase.AABBProducer;
import org.dyn4j.collision.broadphase.BroadphaseDetector;
import org.dyn4j.collision.broadphase.BroadphaseFilter;
import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;

/**
 * A dyn4j broad phase whose per-step {@link #update()} skips the fixed bodies that have not moved.
 *
 * <p>dyn4j recomputes every body's box at every physics step, walls and fixed boxes included, and
 * then finds it inside the grown box it already has: for a fixed body at the same place that update
 * changes nothing. Here the items are updated in the tree's own order (the order they were added),
 * each moving body as before and a fixed body only when its transform, or the previous transform a
 * swept box is made from, differs from its last update's (the supervisor may teleport a fixed box).
 * Every other call goes to the tree as is.
 */
final class StillFixedBodies<T> implements BroadphaseDetector<T> {
    private final BroadphaseDetector<T> tree;
    private final Function<T, Body> bodyOf;
    /** Every item in the order the tree holds it, with the transforms of a fixed body's last update (null for the others). */
    private final Map<T, Transform[]> items = new LinkedHashMap<>();

    StillFixedBodies(BroadphaseDetector<T> tree, Function<T, Body> bodyOf) {
        this.tree = tree;
        this.bodyOf = bodyOf;
    }

    @Override
    public void update() {
        for (Map.Entry<T, Transform[]> e : items.entrySet()) {
            Transform[] last = e.getValue();
            if (last == null || moved(bodyOf.apply(e.getKey()), last)) {
                tree.update(e.getKey());
            }
        }
    }

    private static boolean moved(Body body, Transform[] last) {
        boolean moved = !same(body.getTransform(), last[0]) || !same(body.getPreviousTransform(), last[1]);
        if (moved) {
            last[0].set(body.getTransform());
            last[1].set(body.getPreviousTransform());
        }
        return moved;
    }

    private static boolean same(Transform a, Transform b) {
        return a.getTranslationX() == b.getTranslationX() && a.getTranslationY() == b.getTranslationY()
                && a.getCost() == b.getCost() && a.getSint() == b.getSint();
    }

    private void track(T item) {
        if (!items.containsKey(item)) {
            Body body = bodyOf.apply(item);
            items.put(item, BroadPhases.fixed(body)
                    ? new Transform[] {body.getTransform().copy(), body.getPreviousTransform().copy()}
                    : null);
        }
    }

    @Override
    public void add(T object) {
        tree.add(object);
        track(object);
    }

    @Override
    public void update(T object) {
        tree.update(object); // adds an item the tree does not hold
        track(object);
    }

    @Override
    public boolean remove(T object) {
        items.remove(object);
        return tree.remove(object);
    }

    @Override
    public void clear() {
        items.clear();
        tree.clear();
    }

    @Override
    public void setUpdated(T object) {
        tree.setUpdated(object);
    }

    @Override
    public boolean isUpdated(T object) {
        return tree.isUpdated(object);
    }

    @Override
    public void clearUpdates() {
        tree.clearUpdates();
    }

    @Override
    public AABB getAABB(T object) {
        return tree.getAABB(object);
    }

    @Override
    public boolean contains(T object) {
        return tree.contains(object);
    }

    @Override
    public int size() {
        return tree.size();
    }

    @Override
    public List<CollisionPair<T>> detect() {
        return tree.detect();
    }

    @Override
    public List<CollisionPair<T>> detect(boolean forceFullDetection) {
        return tree.detect(forceFullDetection);
    }

    @Override
    public Iterator<CollisionPair<T>> detectIterator() {
        return tree.detectIterator();
    }

    @Override
    public Iterator<CollisionPair<T>> detectIterator(boolean forceFullDetection) {
        return tree.detectIterator(forceFullDetection);
    }

    @Override
    public List<T> detect(AABB aabb) {
        return tree.detect(aabb);
    }

    @Override
    public Iterator<T> detectIterator(AABB aabb) {
        return tree.detectIterator(aabb);
    }

    @Override
    public List<T> raycast(Ray ray, double length) {
        return tree.raycast(ray, length);
    }

    @Override
    public Iterator<T> raycastIterator(Ray ray, double length) {
        return tree.raycastIterator(ray, length);
    }

    @Override
    public boolean detect(T a, T b) {
        return tree.detect(a, b);
    }

    @Override
    public boolean detect(Convex convex1, Transform transform1, Convex convex2, Transform transform2) {
        return tree.detect(convex1, transform1, convex2, transform2);
    }

    @Override
    public AABBProducer<T> getAABBProducer() {
        return tree.getAABBProducer();
    }

    @Override
    public AABBExpansionMethod<T> getAABBExpansionMethod() {
        return tree.getAABBExpansionMethod();
    }

    @Override
    public BroadphaseFilter<T> getBroadphaseFilter() {
        return tree.getBroadphaseFilter();
    }

    @Override
    public boolean isUpdateTrackingSupported() {
        return tree.isUpdateTrackingSupported();
    }

    @Override
    public boolean isUpdateTrackingEnabled() {
        return tree.isUpdateTrackingEnabled();
    }

    @Override
    public void setUpdateTrackingEnabled(boolean flag) {
        tree.setUpdateTrackingEnabled(flag);
    }

    @Override
    public void optimize() {
        tree.optimize();
    }

    @Override
    public void shift(Vector2 shift) {
        tree.shift(shift);
    }
}
