package jacabot.cartago;

import java.util.List;

/**
 * What an agent perceives from the artifacts of a workspace; registered once per agent by
 * {@link Workspace#join(String, ArtifactObserver)}. Values are plain Java objects.
 *
 * <p>Calls for one artifact arrive in commit order. In threaded mode they run on the operation's
 * thread while it holds the artifact; in stepped mode on the thread calling
 * {@link Workspace#runPending()}. Either way they must return quickly and must not block (queue the
 * event for the agent); an exception is logged and does not affect the artifact.
 */
public interface ArtifactObserver {
    /** The agent now focuses {@code artifact}, whose committed properties are {@code properties}. */
    void focused(ArtifactId artifact, List<PropertySnapshot> properties);

    /** A focused artifact defined a new property. */
    void propertyAdded(ArtifactId artifact, PropertySnapshot property);

    /** A property of a focused artifact changed value (only reported when the values differ). */
    void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue);

    /** A focused artifact removed a property. */
    void propertyRemoved(ArtifactId artifact, PropertySnapshot property);

    /** A focused artifact signalled {@code type(args...)}, or signalled it to this agent alone. */
    void signalled(ArtifactId artifact, String type, List<Object> args);

    /**
     * The agent no longer observes {@code artifact}, by {@code stopFocus}, by disposal of the
     * artifact or by leaving the workspace; {@code properties} are the ones to forget.
     */
    void focusEnded(ArtifactId artifact, List<PropertySnapshot> properties, boolean disposed);
}
