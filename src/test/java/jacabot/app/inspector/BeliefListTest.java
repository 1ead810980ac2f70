package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The probe's list of belief groups reads as the list of their beliefs in order, empty groups among them. */
class BeliefListTest {
    private static MindState.Belief b(String text) {
        return new MindState.Belief(text, List.of(), List.of());
    }

    @Test
    void itReadsAsTheGroupsBeliefsInOrderPastEmptyGroups() {
        var empty = new MindState.Belief[0];
        MindState.Belief[][] groups = {empty, {b("a"), b("b")}, empty, empty, {b("c")}, {b("d"), b("e"), b("f")}, empty};
        var list = new BeliefList(groups, groups.length);
        var flat = new ArrayList<MindState.Belief>();
        for (MindState.Belief[] g : groups) {
            flat.addAll(List.of(g));
        }
        assertEquals(6, list.size());
        assertEquals(flat, list);
        assertEquals(list, flat);
        for (int i = 0; i < flat.size(); i++) {
            assertEquals(flat.get(i), list.get(i), "at " + i);
        }
        assertEquals(flat, new ArrayList<>(list), "by its iterator");
        assertThrows(IndexOutOfBoundsException.class, () -> list.get(6));
        assertThrows(UnsupportedOperationException.class, () -> list.add(b("g")));
        assertEquals(List.of(), BeliefList.EMPTY);
    }

    @Test
    void aMindStateKeepsTheListItIsGiven() {
        var list = new BeliefList(new MindState.Belief[][] {{b("a")}}, 1);
        var m = new MindState("robot", 1, 0, 0, list, List.of(), List.of(), List.of());
        assertEquals(list, m.beliefs());
        assertSame(list, m.beliefs(), "not copied: it is immutable");
    }
}
