package jacabot.cartago;

import java.util.List;

/** An {@link ArtifactObserver} that ignores everything; extend it to handle some events only. */
public class ArtifactObserverAdapter implements ArtifactObserver {
    @Override
    public void focused(ArtifactId artifact, List<PropertySnapshot> properties) {
    }

    @Override
    public void propertyAdded(ArtifactId artifact, PropertySnapshot property) {
    }

    @Override
    public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
    }

    @Override
    public void propertyRemoved(ArtifactId artifact, PropertySnapshot property) {
    }

    @Override
    public void signalled(ArtifactId artifact, String type, List<Object> args) {
    }

    @Override
    public void focusEnded(ArtifactId artifact, List<PropertySnapshot> properties, boolean disposed) {
    }
}
