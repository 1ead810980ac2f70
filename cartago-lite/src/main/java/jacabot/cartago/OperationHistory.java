package jacabot.cartago;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The operation log of one artifact: the last N completed operations of each agent, so that an
 * agent calling often (a host delivering readings every step) does not push the others out.
 * Written by the operations' carriers, read by any thread.
 */
final class OperationHistory {
    /** A record and its place in the artifact's order of completion. */
    private record Numbered(long number, OperationRecord record) {
    }

    private final Map<String, ArrayDeque<Numbered>> byAgent = new LinkedHashMap<>();
    private long completed;

    synchronized void add(OperationRecord record, int lastN) {
        ArrayDeque<Numbered> kept = byAgent.computeIfAbsent(record.agent(), a -> new ArrayDeque<>());
        kept.addLast(new Numbered(completed++, record));
        while (kept.size() > lastN) {
            kept.removeFirst();
        }
    }

    /** {@return the records kept, in the order the operations completed} */
    synchronized List<OperationRecord> records() {
        List<Numbered> all = new ArrayList<>();
        byAgent.values().forEach(all::addAll);
        all.sort(Comparator.comparingLong(Numbered::number));
        return all.stream().map(Numbered::record).toList();
    }
}
