package jacabot.cartago.remote;

import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.OpFeedbackParam;
import jacabot.cartago.PropertySnapshot;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.lang.reflect.Array;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.function.UnaryOperator;

/**
 * The values that cross between a node and its remote agents, each behind a tag, and nothing else:
 * no Java serialization, no class named by the peer. The allowed shapes are null, booleans, ints,
 * longs, doubles, strings, lists of allowed values, artifact ids, agent ids and the marker of an
 * output parameter. Reading refuses any other tag, strings over 1 MiB, lists over 100,000
 * elements and nesting deeper than 32. Artifact ids carry the workspace's name as the reading end
 * calls it ({@code rename}), so that ids of a remote {@code main} never equal ids of the local one.
 */
final class Wire {
    static final int MAX_STRING = 1 << 20;
    static final int MAX_LIST = 100_000;
    static final int MAX_DEPTH = 32;

    private static final int NULL = 0;
    private static final int TRUE = 1;
    private static final int FALSE = 2;
    private static final int INT = 3;
    private static final int LONG = 4;
    private static final int DOUBLE = 5;
    private static final int STRING = 6;
    private static final int LIST = 7;
    private static final int ARTIFACT = 8;
    private static final int AGENT = 9;
    private static final int OUTPUT = 10;

    /** A value of a shape that may not cross: the writer refuses it before anything is sent. */
    static final class NotTransferable extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        NotTransferable(Object value) {
            super("a " + value.getClass().getName() + " cannot be sent to or from a remote workspace "
                    + "(numbers, strings, booleans, lists and artifact ids can)");
        }
    }

    private Wire() {
    }

    /** @throws NotTransferable for a value of another shape (checked by {@link #check} first) */
    static void write(DataOutputStream out, Object v, UnaryOperator<String> rename) throws IOException {
        if (v == null) {
            out.writeByte(NULL);
        } else if (v instanceof Boolean b) {
            out.writeByte(b ? TRUE : FALSE);
        } else if (v instanceof Integer || v instanceof Short || v instanceof Byte) {
            out.writeByte(INT);
            out.writeInt(((Number) v).intValue());
        } else if (v instanceof Long l) {
            out.writeByte(LONG);
            out.writeLong(l);
        } else if (v instanceof Double || v instanceof Float) {
            out.writeByte(DOUBLE);
            out.writeDouble(((Number) v).doubleValue());
        } else if (v instanceof String || v instanceof Character || v instanceof Enum) {
            out.writeByte(STRING);
            writeString(out, v instanceof Enum<?> e ? e.name() : v.toString());
        } else if (v instanceof Collection<?> c) {
            out.writeByte(LIST);
            out.writeInt(c.size());
            for (Object o : c) {
                write(out, o, rename);
            }
        } else if (v.getClass().isArray()) {
            out.writeByte(LIST);
            int n = Array.getLength(v);
            out.writeInt(n);
            for (int i = 0; i < n; i++) {
                write(out, Array.get(v, i), rename);
            }
        } else if (v instanceof ArtifactId a) {
            out.writeByte(ARTIFACT);
            out.writeInt(a.id());
            writeString(out, a.name());
            writeString(out, a.type());
            writeString(out, rename.apply(a.workspace()));
            write(out, a.creator() == null ? null : a.creator().name(), rename);
        } else if (v instanceof AgentId a) {
            out.writeByte(AGENT);
            writeString(out, a.name());
        } else if (v instanceof OpFeedbackParam) {
            out.writeByte(OUTPUT);
        } else {
            throw new NotTransferable(v);
        }
    }

    /** @throws NotTransferable when {@code v} holds a value of a shape that may not cross */
    static void check(Object v) {
        if (v == null || v instanceof Boolean || v instanceof Integer || v instanceof Short || v instanceof Byte
                || v instanceof Long || v instanceof Double || v instanceof Float || v instanceof String || v instanceof Character || v instanceof Enum || v instanceof ArtifactId
                || v instanceof AgentId || v instanceof OpFeedbackParam) {
            return;
        }
        if (v instanceof Collection<?> c) {
            c.forEach(Wire::check);
        } else if (v.getClass().isArray()) {
            for (int i = 0; i < Array.getLength(v); i++) {
                check(Array.get(v, i));
            }
        } else {
            throw new NotTransferable(v);
        }
    }

    /** {@return {@code v} with every value of a shape that may not cross replaced by its text} */
    static Object transferable(Object v) {
        if (v instanceof Collection<?> c) {
            var out = new ArrayList<Object>(c.size());
            c.forEach(o -> out.add(transferable(o)));
            return out;
        }
        if (v != null && v.getClass().isArray()) {
            var out = new ArrayList<Object>();
            for (int i = 0; i < Array.getLength(v); i++) {
                out.add(transferable(Array.get(v, i)));
            }
            return out;
        }
        try {
            check(v);
            return v;
        } catch (NotTransferable e) {
            return String.valueOf(v);
        }
    }

    static Object read(DataInputStream in, UnaryOperator<String> rename) throws IOException {
        return read(in, rename, 0);
    }

    private static Object read(DataInputStream in, UnaryOperator<String> rename, int depth) throws IOException {
        if (depth > MAX_DEPTH) {
            throw new IOException("values nested deeper than " + MAX_DEPTH);
        }
        int tag = in.readUnsignedByte();
        switch (tag) {
            case NULL: return null;
            case TRUE: return Boolean.TRUE;
            case FALSE: return Boolean.FALSE;
            case INT: return in.readInt();
            case LONG: return in.readLong();
            case DOUBLE: return in.readDouble();
            case STRING: return readString(in);
            case LIST: {
                int n = in.readInt();
                if (n < 0 || n > MAX_LIST) {
                    throw new IOException("a list of " + n + " elements");
                }
                var items = new ArrayList<Object>(Math.min(n, 1024));
                for (int i = 0; i < n; i++) {
                    items.add(read(in, rename, depth + 1));
                }
                return items;
            }
            case ARTIFACT: {
                int id = in.readInt();
                String name = readString(in);
                String type = readString(in);
                String workspace = rename.apply(readString(in));
                Object creator = read(in, rename, depth + 1);
                if (creator != null && !(creator instanceof String)) {
                    throw new IOException("an artifact id whose creator is not a name");
                }
                return new ArtifactId(id, name, type, workspace, creator == null ? null : new AgentId((String) creator));
            }
            case AGENT: return new AgentId(readString(in));
            case OUTPUT: return new OpFeedbackParam<Object>();
            default: throw new IOException("unknown value tag " + tag);
        }
    }

    static void writeString(DataOutputStream out, String s) throws IOException {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        if (b.length > MAX_STRING) {
            throw new IOException("a string of " + b.length + " bytes is too long for a remote workspace");
        }
        out.writeInt(b.length);
        out.write(b);
    }

    static String readString(DataInputStream in) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > MAX_STRING) {
            throw new IOException("a string of " + n + " bytes");
        }
        byte[] b = new byte[n];
        in.readFully(b);
        return new String(b, StandardCharsets.UTF_8);
    }

    /** Writes a property; values of shapes that may not cross travel as their text. */
    static void writeProperty(DataOutputStream out, PropertySnapshot p, UnaryOperator<String> rename) throws IOException {
        writeString(out, p.name());
        write(out, transferable(p.values()), rename);
    }

    static PropertySnapshot readProperty(DataInputStream in, UnaryOperator<String> rename) throws IOException {
        String name = readString(in);
        Object values = read(in, rename);
        if (!(values instanceof List<?> l)) {
            throw new IOException("a property without its list of values");
        }
        return new PropertySnapshot(name, new ArrayList<>(l));
    }

    static void writeProperties(DataOutputStream out, List<PropertySnapshot> ps, UnaryOperator<String> rename)
            throws IOException {
        out.writeInt(ps.size());
        for (PropertySnapshot p : ps) {
            writeProperty(out, p, rename);
        }
    }

    static List<PropertySnapshot> readProperties(DataInputStream in, UnaryOperator<String> rename) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > MAX_LIST) {
            throw new IOException(n + " properties");
        }
        var out = new ArrayList<PropertySnapshot>();
        for (int i = 0; i < n; i++) {
            out.add(readProperty(in, rename));
        }
        return out;
    }
}
