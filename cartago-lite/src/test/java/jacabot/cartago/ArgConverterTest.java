package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.lang.reflect.Method;
import java.util.List;
import org.junit.jupiter.api.Test;

class ArgConverterTest {
    enum Dir { LEFT, RIGHT }

    @SuppressWarnings("unused")
    private static final class Target {
        void prims(int i, long l, short s, double d, float f, boolean b, char c) {
        }

        void things(Dir dir, double[] values, List<Object> list, String text) {
        }

        void varargs(String head, Object... rest) {
        }
    }

    private static Method method(String name) {
        for (Method m : Target.class.getDeclaredMethods()) {
            if (m.getName().equals(name)) {
                return m;
            }
        }
        throw new AssertionError(name);
    }

    @Test
    void primitivesAcceptAnyNumberThatFits() throws Exception {
        Object[] out = ArgConverter.convertAll(method("prims"), new Object[] {5.0, 7, 3.0, 2, 1.5, true, "x"});
        assertArrayEquals(new Object[] {5, 7L, (short) 3, 2.0, 1.5f, true, 'x'}, out);
        assertThrows(ArgConverter.Mismatch.class,
                () -> ArgConverter.convertAll(method("prims"), new Object[] {1e12, 7, 3, 2, 1, true, "x"}));
        assertThrows(ArgConverter.Mismatch.class,
                () -> ArgConverter.convertAll(method("prims"), new Object[] {1, 7, 3, 2, 1, "yes", "x"}));
    }

    @Test
    void enumsArraysListsAndStrings() throws Exception {
        Object[] out = ArgConverter.convertAll(method("things"), new Object[] {"left", List.of(1, 2.5), new Object[] {1.0}, Dir.RIGHT});
        assertEquals(Dir.LEFT, out[0]);
        assertArrayEquals(new double[] {1, 2.5}, (double[]) out[1]);
        assertEquals(List.of(1.0), out[2]);
        assertEquals("RIGHT", out[3]);
    }

    @Test
    void varargsPackTheTrailingArguments() throws Exception {
        Object[] out = ArgConverter.convertAll(method("varargs"), new Object[] {"h", 1.0, "b"});
        assertArrayEquals(new Object[] {1, "b"}, (Object[]) out[1]);
        out = ArgConverter.convertAll(method("varargs"), new Object[] {"h"});
        assertArrayEquals(new Object[0], (Object[]) out[1]);
    }
}
