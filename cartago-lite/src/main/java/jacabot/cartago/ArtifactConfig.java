package jacabot.cartago;

import java.util.Arrays;

/**
 * CArtAgO's parameters of an artifact's {@code init}, for {@link Artifact#makeArtifact} called
 * from inside another artifact: {@code new ArtifactConfig(taskDescr, duration)}, or
 * {@link #DEFAULT_CONFIG} for none.
 */
public final class ArtifactConfig {
    /** No parameters. */
    public static final ArtifactConfig DEFAULT_CONFIG = new ArtifactConfig();

    private final Object[] params;

    public ArtifactConfig(Object... params) {
        this.params = params == null ? new Object[0] : params.clone();
    }

    /** {@return a copy of the parameters} */
    public Object[] getParams() {
        return params.clone();
    }

    public Object get(int index) {
        return params[index];
    }

    public int getInt(int index) {
        return ((Number) params[index]).intValue();
    }

    public long getLong(int index) {
        return ((Number) params[index]).longValue();
    }

    public double getDouble(int index) {
        return ((Number) params[index]).doubleValue();
    }

    public String getString(int index) {
        return String.valueOf(params[index]);
    }

    public int getLength() {
        return params.length;
    }

    @Override
    public String toString() {
        return "ArtifactConfig" + Arrays.toString(params);
    }
}
