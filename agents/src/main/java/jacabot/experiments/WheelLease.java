package jacabot.experiments;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * Who may command a robot's wheels when several agents share its middleware artifact (not in the
 * thesis: its Chapter 6 wish, "the single robot programmed by more agents"). At most one agent holds
 * the wheels, and once some agent has taken them only the holder's wheel commands go through (the
 * others', and anyone's while they are released, are refused). Until some agent first takes them
 * every agent may command them, as with the thesis' one agent per robot.
 *
 * <p>Where the runner marks control steps ({@link #endStep}, lockstep), the wheels also have one
 * driver per step: a second agent's command in a step another has driven is refused, and the wheels
 * change hands only at a step's end, so no step carries two agents' commands to the robot.
 */
public final class WheelLease {
    private String holder;
    /** Some agent has taken the wheels: from now on only the holder drives. */
    private boolean leased;
    /** The agents whose commands went through in this control step, in order. */
    private final Set<String> drivers = new LinkedHashSet<>();
    private boolean stepped;
    private long refusals;
    private final Map<String, Long> stepsDriven = new TreeMap<>();
    private long twoDrivers;

    /** {@return the agent holding the wheels; empty while nobody does} */
    public synchronized Optional<String> holder() {
        return Optional.ofNullable(holder);
    }

    /**
     * {@return whether {@code agent} may take the wheels now: nobody holds them, or it does, and no
     * other agent has driven them in this step}
     */
    public synchronized boolean isFreeFor(String agent) {
        return (holder == null || holder.equals(agent)) && !drivenByAnother(agent);
    }

    private boolean drivenByAnother(String agent) {
        return stepped && !drivers.isEmpty() && !(drivers.size() == 1 && drivers.contains(agent));
    }

    /** {@code agent} holds the wheels. @throws IllegalStateException if another one does */
    public synchronized void hold(String agent) {
        if (!isFreeFor(agent)) {
            throw new IllegalStateException(agent + " cannot take the wheels: " + holder + " holds them");
        }
        holder = agent;
        leased = true;
    }

    /** {@return whether {@code agent} held the wheels and has now let them go} (not holding them: nothing happens) */
    public synchronized boolean release(String agent) {
        if (holder == null || !holder.equals(agent)) {
            return false;
        }
        holder = null;
        return true;
    }

    /**
     * Checks a wheel command of {@code agent}: {@return empty when it may go (noted as this step's),
     * else why not (counted as a refusal)}
     */
    public synchronized Optional<String> command(String agent) {
        if (leased && !agent.equals(holder)) {
            refusals++;
            return Optional.of(holder == null ? "nobody holds the wheels (acquireWheels first)" : holder + " holds the wheels");
        }
        if (drivenByAnother(agent)) {
            refusals++;
            return Optional.of(drivers.iterator().next() + " has driven the wheels in this control step");
        }
        drivers.add(agent);
        return Optional.empty();
    }

    /** {@return the agents whose wheel commands went through in this control step so far, in order} */
    public synchronized List<String> drivers() {
        return new ArrayList<>(drivers);
    }

    /** Ends a control step (the runner has taken its commands): {@return the step's drivers, in order} */
    public synchronized List<String> endStep() {
        stepped = true;
        var out = new ArrayList<>(drivers);
        drivers.clear();
        out.forEach(a -> stepsDriven.merge(a, 1L, Long::sum));
        if (out.size() > 1) {
            twoDrivers++; // a check of the rule: command() refuses a second driver, so this stays 0
        }
        return out;
    }

    /** {@return for each agent, the control steps in which its wheel commands went through} */
    public synchronized Map<String, Long> stepsDriven() {
        return new TreeMap<>(stepsDriven);
    }

    /** {@return the control steps in which two or more agents' wheel commands went through} */
    public synchronized long stepsWithTwoDrivers() {
        return twoDrivers;
    }

    /** {@return the wheel commands refused so far} */
    public synchronized long refusals() {
        return refusals;
    }
}
