package jacabot.cartago;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The methods each method of a class file calls, read from its bytecode (JVM spec §4): the
 * {@code invoke*} instructions, the classes it instantiates, and the method handles of its
 * {@code invokedynamic} bootstrap arguments (a lambda's body or a method reference). Nothing is
 * loaded or run. The JDK before 22 has no class-file reader, and this needs only the call graph.
 */
final class ClassFileCalls {
    /** A method called (or instantiated class, as {@code <new>}), by its owner's internal name. */
    record Call(String owner, String name, String descriptor) {
    }

    private final Map<String, List<Call>> calls = new LinkedHashMap<>();

    private ClassFileCalls() {
    }

    /** {@return the calls of each method, keyed by name + descriptor} @throws IOException for a malformed class file */
    static Map<String, List<Call>> read(InputStream classFile) throws IOException {
        ClassFileCalls result = new ClassFileCalls();
        result.parse(new DataInputStream(classFile));
        return result.calls;
    }

    private Object[] pool;
    private int[] tags;

    private void parse(DataInputStream in) throws IOException {
        if (in.readInt() != 0xCAFEBABE) {
            throw new IOException("not a class file");
        }
        in.readUnsignedShort(); // minor
        in.readUnsignedShort(); // major
        readPool(in);
        in.readUnsignedShort(); // access
        in.readUnsignedShort(); // this
        in.readUnsignedShort(); // super
        in.skipNBytes(2L * in.readUnsignedShort()); // interfaces
        int fields = in.readUnsignedShort();
        for (int i = 0; i < fields; i++) {
            in.skipNBytes(6);
            skipAttributes(in);
        }
        Map<String, byte[]> code = new LinkedHashMap<>();
        int methods = in.readUnsignedShort();
        for (int i = 0; i < methods; i++) {
            in.readUnsignedShort();
            String key = utf8(in.readUnsignedShort()) + utf8(in.readUnsignedShort());
            int attributes = in.readUnsignedShort();
            byte[] body = null;
            for (int a = 0; a < attributes; a++) {
                String name = utf8(in.readUnsignedShort());
                byte[] data = in.readNBytes(in.readInt());
                if (name.equals("Code")) {
                    body = data;
                }
            }
            code.put(key, body);
        }
        List<List<Integer>> bootstrapArgs = new ArrayList<>();
        int attributes = in.readUnsignedShort();
        for (int a = 0; a < attributes; a++) {
            String name = utf8(in.readUnsignedShort());
            byte[] data = in.readNBytes(in.readInt());
            if (name.equals("BootstrapMethods")) {
                var bm = new DataInputStream(new ByteArrayInputStream(data));
                int n = bm.readUnsignedShort();
                for (int i = 0; i < n; i++) {
                    bm.readUnsignedShort();
                    List<Integer> args = new ArrayList<>();
                    int count = bm.readUnsignedShort();
                    for (int j = 0; j < count; j++) {
                        args.add(bm.readUnsignedShort());
                    }
                    bootstrapArgs.add(args);
                }
            }
        }
        for (var e : code.entrySet()) {
            calls.put(e.getKey(), e.getValue() == null ? List.of() : scan(e.getValue(), bootstrapArgs));
        }
    }

    private void readPool(DataInputStream in) throws IOException {
        int count = in.readUnsignedShort();
        pool = new Object[count];
        tags = new int[count];
        for (int i = 1; i < count; i++) {
            int tag = in.readUnsignedByte();
            tags[i] = tag;
            switch (tag) {
                case 1 -> pool[i] = in.readUTF();
                case 3, 4 -> in.skipNBytes(4);
                case 5, 6 -> {
                    in.skipNBytes(8);
                    i++; // takes two slots
                }
                case 7, 8, 16, 19, 20 -> pool[i] = new int[] {in.readUnsignedShort()};
                case 9, 10, 11, 12, 17, 18 -> pool[i] = new int[] {in.readUnsignedShort(), in.readUnsignedShort()};
                case 15 -> pool[i] = new int[] {in.readUnsignedByte(), in.readUnsignedShort()};
                default -> throw new IOException("unknown constant pool tag " + tag + " at " + i);
            }
        }
    }

    private static void skipAttributes(DataInputStream in) throws IOException {
        int count = in.readUnsignedShort();
        for (int i = 0; i < count; i++) {
            in.readUnsignedShort();
            in.skipNBytes(in.readInt() & 0xFFFFFFFFL);
        }
    }

    private String utf8(int index) throws IOException {
        if (index <= 0 || index >= pool.length || tags[index] != 1) {
            throw new IOException("constant " + index + " is not a name");
        }
        return (String) pool[index];
    }

    private int[] entry(int index, int... expected) throws IOException {
        if (index > 0 && index < pool.length) {
            for (int tag : expected) {
                if (tags[index] == tag) {
                    return (int[]) pool[index];
                }
            }
        }
        throw new IOException("constant " + index + " has tag " + (index > 0 && index < pool.length ? tags[index] : -1));
    }

    private String className(int index) throws IOException {
        return utf8(entry(index, 7)[0]);
    }

    /** A Methodref or InterfaceMethodref (or Fieldref, for a handle to a field). */
    private Call member(int index) throws IOException {
        int[] ref = entry(index, 9, 10, 11);
        int[] nameAndType = entry(ref[1], 12);
        return new Call(className(ref[0]), utf8(nameAndType[0]), utf8(nameAndType[1]));
    }

    private List<Call> scan(byte[] attribute, List<List<Integer>> bootstrapArgs) throws IOException {
        var in = new DataInputStream(new ByteArrayInputStream(attribute));
        in.skipNBytes(4); // max stack, max locals
        byte[] code = in.readNBytes(in.readInt());
        List<Call> found = new ArrayList<>();
        int pc = 0;
        while (pc < code.length) {
            int op = code[pc] & 0xFF;
            switch (op) {
                case 0xB6, 0xB7, 0xB8, 0xB9 -> found.add(member(u2(code, pc + 1)));
                case 0xBA -> {
                    int[] indy = entry(u2(code, pc + 1), 18);
                    if (indy[0] >= bootstrapArgs.size()) {
                        throw new IOException("invokedynamic names bootstrap method " + indy[0]);
                    }
                    for (int arg : bootstrapArgs.get(indy[0])) {
                        if (arg > 0 && arg < tags.length && tags[arg] == 15) {
                            found.add(member(((int[]) pool[arg])[1]));
                        }
                    }
                }
                case 0xBB -> found.add(new Call(className(u2(code, pc + 1)), "<new>", ""));
                default -> {
                }
            }
            pc += length(code, pc);
        }
        return found;
    }

    private static int u2(byte[] code, int at) {
        return (code[at] & 0xFF) << 8 | code[at + 1] & 0xFF;
    }

    private static int s4(byte[] code, int at) {
        return (code[at] & 0xFF) << 24 | (code[at + 1] & 0xFF) << 16 | (code[at + 2] & 0xFF) << 8 | code[at + 3] & 0xFF;
    }

    /** {@return the length of the instruction at {@code pc}} */
    private static int length(byte[] code, int pc) throws IOException {
        int op = code[pc] & 0xFF;
        if (op == 0xAA || op == 0xAB) {
            int at = (pc + 4) & ~3; // operands start 4-byte aligned
            if (op == 0xAA) {
                int low = s4(code, at + 4);
                int high = s4(code, at + 8);
                return at + 12 + 4 * (high - low + 1) - pc;
            }
            return at + 8 + 8 * s4(code, at + 4) - pc;
        }
        if (op == 0xC4) { // wide
            return (code[pc + 1] & 0xFF) == 0x84 ? 6 : 4;
        }
        if (op == 0x10 || op == 0x12 || op >= 0x15 && op <= 0x19 || op >= 0x36 && op <= 0x3A || op == 0xA9 || op == 0xBC) {
            return 2;
        }
        if (op == 0x11 || op == 0x13 || op == 0x14 || op == 0x84 || op >= 0x99 && op <= 0xA8 || op >= 0xB2 && op <= 0xB8
                || op == 0xBB || op == 0xBD || op == 0xC0 || op == 0xC1 || op == 0xC6 || op == 0xC7) {
            return 3;
        }
        if (op == 0xC5) {
            return 4;
        }
        if (op == 0xB9 || op == 0xBA || op == 0xC8 || op == 0xC9) {
            return 5;
        }
        if (op > 0xC9) {
            throw new IOException("unknown opcode " + op + " at " + pc);
        }
        return 1;
    }
}
