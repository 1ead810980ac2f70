package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class OpFeedbackParamTest {
    @Test
    void holdsTheLastValueSetByTheOperation() {
        var param = new OpFeedbackParam<Integer>();
        assertFalse(param.isSet());
        assertNull(param.get());
        param.set(3);
        param.set(5);
        assertTrue(param.isSet());
        assertEquals(5, param.get());
    }
}
