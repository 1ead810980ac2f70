package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.PriorityQueue;
import java.util.Random;
import org.junit.jupiter.api.Test;

class CellQueueTest {
    @Test
    void cellsComeOutInThePriorityQueuesOrderEqualCostsIncluded() {
        Random random = new Random(11);
        CellQueue queue = new CellQueue();
        for (int round = 0; round < 300; round++) {
            queue.clear();
            PriorityQueue<double[]> expected = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
            int costs = 1 + random.nextInt(8); // few distinct costs: many ties
            int cell = 0;
            for (int op = 0; op < 2_000; op++) {
                if (expected.isEmpty() || random.nextInt(3) > 0) {
                    double key = random.nextInt(costs) * 0.5;
                    expected.add(new double[] {key, cell});
                    queue.add(key, cell++);
                } else {
                    assertEquals((int) expected.poll()[1], queue.poll(), "round " + round + ", operation " + op);
                }
            }
            while (!expected.isEmpty()) {
                assertEquals((int) expected.poll()[1], queue.poll());
            }
            assertTrue(queue.isEmpty());
        }
    }
}
