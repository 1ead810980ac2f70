package jacabot.app.console;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class RepeatFolderTest {
    private final List<String> printed = new ArrayList<>();
    private final RepeatFolder folder = new RepeatFolder(printed::add);

    @Test
    void aRunOfOneLineIsPrintedOnceThenCounted() {
        for (int i = 0; i < 12; i++) {
            folder.line("[robot] high left");
        }
        assertEquals(List.of("[robot] high left"), printed, "the first at once, the others held");
        folder.line("[robot] Cylinder picked up");
        folder.flush();
        assertEquals(List.of("[robot] high left", "[robot] high left (x11 more)", "[robot] Cylinder picked up"), printed,
                "the count as soon as the run ends");
    }

    @Test
    void anAvoidanceCycleIsFoldedButItsChangingLinesStay() {
        // the as-published agents' loop near a wall: a new distance each time, the same two lines after it
        for (int i = 0; i < 9; i++) {
            folder.line("[robot] Obstacle: " + (350 + i));
            folder.line("[robot] Wait avoiding");
            folder.line("[robot] high left");
        }
        folder.flush();
        assertEquals(9 + 2 + 2, printed.size(), String.join("\n", printed));
        assertEquals(List.of("[robot] Obstacle: 350", "[robot] Wait avoiding", "[robot] high left", "[robot] Obstacle: 351"),
                printed.subList(0, 4));
        assertEquals(List.of("[robot] Wait avoiding (x8 more)", "[robot] high left (x8 more)"), printed.subList(11, 13));
    }

    @Test
    void aLineOutOfTheWindowIsReportedWhereItsRunEndedAndThenShownAgain() {
        folder.line("[robot] Wait avoiding");
        folder.line("[robot] high left");
        folder.line("[robot] Wait avoiding");
        for (int i = 0; i < RepeatFolder.WINDOW; i++) {
            folder.line("[robot] step " + i);
        }
        // once out of the last eight lines, its count comes out, and a new occurrence is shown as new
        assertEquals("[robot] Wait avoiding (x1 more)", printed.get(2 + RepeatFolder.WINDOW - 1), String.join("\n", printed));
        assertEquals("[robot] step " + (RepeatFolder.WINDOW - 1), printed.get(printed.size() - 1));
        folder.line("[robot] Wait avoiding");
        assertEquals("[robot] Wait avoiding", printed.get(printed.size() - 1));
    }

    @Test
    void linesFarApartAreNeverFolded() {
        for (int i = 0; i < 3; i++) {
            folder.line("[middleware] Target reached");
            for (int j = 0; j < RepeatFolder.WINDOW; j++) {
                folder.line("[robot] " + i + "." + j);
            }
        }
        folder.flush();
        assertEquals(3, printed.stream().filter(l -> l.equals("[middleware] Target reached")).count());
        assertEquals(3 * (1 + RepeatFolder.WINDOW), printed.size());
    }
}
