package jacabot.robot.run;

import com.fasterxml.jackson.annotation.JsonIgnoreProperties;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The outcome of one run, agent or baseline alike: what the scenario tests assert and what
 * {@code jacabot compare} tabulates. Lengths in metres, times in simulated seconds, energy in joules.
 * Written as JSON ({@link #toJson()}, one member per component, in this order) and as a short text
 * block ({@link #toText()}).
 *
 * @param world                      the world's name
 * @param robot                      the robot's name
 * @param controller                 who drove it, e.g. {@code "baseline"} or {@code "agent"}
 * @param seed                       the world seed of the run
 * @param duration                   simulated seconds recorded
 * @param distance                   path length of the robot's centre
 * @param coverage                   share of the arena's grid cells its centre visited, 0..1
 * @param cellSize                   the grid's cell side
 * @param cellsVisited               cells visited
 * @param cells                      cells in the arena
 * @param contactTime                seconds touching walls, boxes, cylinders or robots
 * @param longestContact             the longest uninterrupted contact
 * @param picks                      times the gripper took hold of a cylinder
 * @param pickTimes                  when
 * @param deliveries                 cylinders let go with their centre inside the storage area
 * @param deliveryTimes              when
 * @param lost                       cylinders that left the gripper without being set down (knocked, moved, removed)
 * @param storageEntriesWithCylinder entries of the robot's centre into the storage area while holding a cylinder
 * @param storageEntriesEmpty        entries without one (the thesis forbids coming back empty)
 * @param batteryMin                 lowest energy, null for a robot without battery
 * @param batteryEmptied             whether the energy ever reached 0
 * @param chargerVisits              entries of the robot's centre onto the charger
 * @param recharged                  energy gained over the run (charger, or a supervisor's top-up)
 * @param events                     the event log, one line per event (see {@link RunRecorder})
 */
@JsonIgnoreProperties(ignoreUnknown = true) // a run's summary.json also names its world and agent files
@JsonPropertyOrder({"world", "robot", "controller", "seed", "duration", "distance", "coverage", "cellSize",
        "cellsVisited", "cells", "contactTime", "longestContact", "picks", "pickTimes", "deliveries", "deliveryTimes",
        "lost", "storageEntriesWithCylinder", "storageEntriesEmpty", "batteryMin", "batteryEmptied", "chargerVisits",
        "recharged", "events"})
public record RunSummary(String world, String robot, String controller, long seed, double duration,
                         double distance, double coverage, double cellSize, int cellsVisited, int cells,
                         double contactTime, double longestContact,
                         int picks, List<Double> pickTimes, int deliveries, List<Double> deliveryTimes, int lost,
                         int storageEntriesWithCylinder, int storageEntriesEmpty,
                         Double batteryMin, boolean batteryEmptied, int chargerVisits, double recharged,
                         List<String> events) {

    /** Copies the lists. */
    public RunSummary {
        pickTimes = List.copyOf(pickTimes);
        deliveryTimes = List.copyOf(deliveryTimes);
        events = List.copyOf(events);
    }

    private static ObjectMapper mapper() {
        return new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
    }

    /** {@return this summary as pretty-printed JSON} */
    public String toJson() {
        try {
            return mapper().writeValueAsString(this);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a run summary always serialises", e);
        }
    }

    /** {@return a summary read back from {@link #toJson()}} @throws IOException on malformed JSON */
    public static RunSummary fromJson(String json) throws IOException {
        return mapper().readValue(json, RunSummary.class);
    }

    /** Writes {@link #toJson()} to a file. */
    public void writeJson(Path file) {
        try {
            Files.writeString(file, toJson() + "\n", StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@return the event log as text, one line per event} */
    public String eventLog() {
        return events.isEmpty() ? "" : String.join("\n", events) + "\n";
    }

    /** {@return a few human-readable lines with the figures (not the event log)} */
    public String toText() {
        StringBuilder b = new StringBuilder();
        b.append(f("run: %s, robot %s, %s, seed %d, %.1f s simulated%n", world, robot, controller, seed, duration));
        b.append(f("motion: %.2f m travelled, coverage %.0f%% (%d of %d cells of %.2f m)%n",
                distance, 100 * coverage, cellsVisited, cells, cellSize));
        b.append(f("contact: %.2f s in all, longest %.2f s%n", contactTime, longestContact));
        b.append(f("cylinders: %d picked%s, %d delivered%s, %d lost%n", picks, times(pickTimes), deliveries,
                times(deliveryTimes), lost));
        b.append(f("storage area: %d entr%s with a cylinder, %d without%n", storageEntriesWithCylinder,
                storageEntriesWithCylinder == 1 ? "y" : "ies", storageEntriesEmpty));
        if (batteryMin != null) {
            b.append(f("battery: lowest %.1f J, %s; %d charger visit%s, %.1f J gained%n", batteryMin,
                    batteryEmptied ? "EMPTIED" : "never empty", chargerVisits, chargerVisits == 1 ? "" : "s", recharged));
        }
        return b.toString();
    }

    private static String times(List<Double> ts) {
        if (ts.isEmpty()) {
            return "";
        }
        StringBuilder b = new StringBuilder(" (at");
        for (int i = 0; i < ts.size(); i++) {
            b.append(i == 0 ? " " : ", ").append(f("%.1f s", ts.get(i)));
        }
        return b.append(')').toString();
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }
}
