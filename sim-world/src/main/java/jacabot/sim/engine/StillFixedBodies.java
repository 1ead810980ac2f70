package jacabot.sim.engine;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.function.Function;
import org.dyn4j.collision.CollisionPair;
import org.dyn4j.collision.broadphase.AABBExpansionMethod;
import org.dyn4j.collision.broadphase.AABBProducer;
import org.dyn4j.collision.broadphase.BroadphaseDetector;
import org.dyn4j.collision.broadphase.BroadphaseFilter;
import org.dyn4j.collision.broadphase.DynamicAABBTree;
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
 * A fixed body is compared only while it is watched: from its addition, and from a teleport
 * ({@link TrackedBody#teleported()}), until a step finds it where it was (dyn4j copies its transform
 * to its previous one once, at a step). Nothing else moves a fixed body, so the fixed bodies left
 * out are those the comparison would find still, and with none watched a step walks the moving
 * items alone (the walls and fixed boxes of an arena are most of its items). An item whose box the
 * tree would keep is not handed to the tree, which would look it up in its map to learn that.
 * The tree's questions about one item (does it hold it, was it updated in this step, do two items'
 * boxes overlap), which dyn4j asks for every pair it keeps at every step, are answered from the
 * item's entry, which its body holds ({@link TrackedBody}), with the tree's answers. Every other call
 * goes to the tree as is.
 */
final class StillFixedBodies<T> implements BroadphaseDetector<T> {
    private final DynamicAABBTree<T> tree;
    private final AABBProducer<T> producer;
    private final AABBExpansionMethod<T> expansion;
    /** An item's new box, before the tree is asked to update it. */
    private final AABB fresh = new AABB(0, 0, 0, 0);
    private final Function<T, Body> bodyOf;
    private final Slot<T> slot;
    /** Every item in the order the tree holds it (the order it was added). */
    private final List<Entry<T>> entries = new ArrayList<>();
    /** The items of moving bodies, in the same order. */
    private final List<Entry<T>> moving = new ArrayList<>();
    /** How many fixed items are watched: compared with their last update at each step. */
    private int watched;
    /** Counts the tree's {@link #clearUpdates()}: an entry updated in this round holds the current count. */
    private long round;

    /**
     * @param slot where a body keeps its entry in this tree ({@link TrackedBody}): the questions below
     *             are answered from the entry, without the tree's hash lookups
     */
    StillFixedBodies(DynamicAABBTree<T> tree, Function<T, Body> bodyOf, Slot<T> slot) {
        this.tree = tree;
        this.producer = tree.getAABBProducer();
        this.expansion = tree.getAABBExpansionMethod();
        this.bodyOf = bodyOf;
        this.slot = slot;
    }

    /** Where a body keeps its entry of one tree. */
    interface Slot<T> {
        Entry<T> get(T item);

        void set(T item, Entry<T> entry);
    }

    /**
     * One item of the tree: its box there (the tree's own object, which it resets in place when it
     * moves the item), whether the tree counts it as updated in this round, and for a fixed body the
     * transforms of its last update.
     */
    static final class Entry<T> {
        final T item;
        final Body body;
        /** The transform and previous transform of the last update; null for a moving body. */
        final Transform[] last;
        private final StillFixedBodies<T> tree;
        AABB box;
        long updatedRound = -1;
        /** A fixed item that may have moved since its last update. */
        private boolean watched;

        Entry(T item, Body body, Transform[] last, StillFixedBodies<T> tree) {
            this.item = item;
            this.body = body;
            this.last = last;
            this.tree = tree;
        }

        /** Its body was moved from outside dyn4j's step: a fixed item is compared again. */
        void watch() {
            if (last != null && !watched) {
                watched = true;
                tree.watched++;
            }
        }

        private void unwatch() {
            if (watched) {
                watched = false;
                tree.watched--;
            }
        }
    }

    /**
     * Updates each moving item as dyn4j does and each fixed item that moved, in the tree's order. The
     * tree re-inserts an item (and counts it as updated) exactly when it gives it a new box, which is
     * when the box's bounds change: a box that still holds the item is kept as it is.
     */
    @Override
    public void update() {
        List<Entry<T>> walk = watched == 0 ? moving : entries;
        for (int i = 0, n = walk.size(); i < n; i++) {
            Entry<T> e = walk.get(i);
            if (e.last == null) {
                updateItem(e);
            } else if (e.watched) {
                if (moved(e.body, e.last)) {
                    updateItem(e);
                } else {
                    e.unwatch();
                }
            }
        }
    }

    /**
     * Updates an item as the tree does, without the tree's lookup of the item when the tree would
     * keep it where it is: {@code DynamicAABBTree.updateNode} keeps a box that holds the item's new
     * box and whose perimeter is at most twice the new box grown; that is asked here the same way,
     * with the tree's own box producer and growth.
     */
    private void updateItem(Entry<T> e) {
        AABB box = e.box;
        producer.compute(e.item, fresh);
        if (box.contains(fresh)) {
            expansion.expand(e.item, fresh);
            if (box.getPerimeter() / fresh.getPerimeter() <= 2) {
                return;
            }
        }
        double minX = box.getMinX(), minY = box.getMinY(), maxX = box.getMaxX(), maxY = box.getMaxY();
        tree.update(e.item);
        if (box.getMinX() != minX || box.getMinY() != minY || box.getMaxX() != maxX || box.getMaxY() != maxY) {
            e.updatedRound = round;
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

    /** {@return the item's entry, or null when the tree does not hold it} */
    private Entry<T> entry(T item) {
        Entry<T> e = slot.get(item);
        return e != null && item.equals(e.item) ? e : null;
    }

    /** After the tree was asked to add or update an item: its entry, made if new, and what the tree says of it. */
    private void track(T item) {
        Entry<T> e = entry(item);
        if (e == null) {
            Body body = bodyOf.apply(item);
            e = new Entry<>(item, body, BroadPhases.fixed(body)
                    ? new Transform[] {body.getTransform().copy(), body.getPreviousTransform().copy()}
                    : null, this);
            entries.add(e);
            if (e.last == null) {
                moving.add(e);
            }
            e.watch(); // its previous transform is not yet dyn4j's
            slot.set(item, e);
        }
        e.box = tree.getAABB(item);
        e.updatedRound = tree.isUpdated(item) ? round : -1;
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
        Entry<T> e = entry(object);
        if (e != null) {
            e.unwatch();
            entries.remove(e);
            moving.remove(e);
            slot.set(object, null);
        }
        return tree.remove(object);
    }

    @Override
    public void clear() {
        for (Entry<T> e : entries) {
            slot.set(e.item, null);
        }
        entries.clear();
        moving.clear();
        watched = 0;
        tree.clear();
    }

    @Override
    public void setUpdated(T object) {
        tree.setUpdated(object);
        Entry<T> e = entry(object);
        if (e != null) {
            e.updatedRound = tree.isUpdated(object) ? round : -1;
        }
    }

    /** As the tree answers: held, and updated since the last {@link #clearUpdates()}. */
    @Override
    public boolean isUpdated(T object) {
        if (!tree.isUpdateTrackingEnabled()) {
            return tree.isUpdated(object);
        }
        Entry<T> e = entry(object);
        return e != null && e.updatedRound == round;
    }

    @Override
    public void clearUpdates() {
        tree.clearUpdates();
        round++;
    }

    @Override
    public AABB getAABB(T object) {
        Entry<T> e = entry(object);
        return e != null ? e.box : tree.getAABB(object);
    }

    @Override
    public boolean contains(T object) {
        return entry(object) != null;
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

    /** As the tree answers for two items it holds: whether their boxes overlap. */
    @Override
    public boolean detect(T a, T b) {
        Entry<T> ea = entry(a), eb = entry(b);
        return ea != null && eb != null ? ea.box.overlaps(eb.box) : tree.detect(a, b);
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
        if (tree.isUpdateTrackingEnabled() != flag) {
            round++; // the tree forgets its updates when tracking stops; none are counted when it starts again
        }
        tree.setUpdateTrackingEnabled(flag);
    }

    @Override
    public void optimize() {
        tree.optimize();
        refreshBoxes();
    }

    @Override
    public void shift(Vector2 shift) {
        tree.shift(shift);
        refreshBoxes();
    }

    private void refreshBoxes() {
        for (Entry<T> e : entries) {
            e.box = tree.getAABB(e.item);
        }
    }
}
