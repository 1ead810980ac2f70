package jacabot.agent.runtime;

import jacabot.agent.semantics.Message;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

/**
 * The directory facilitator of the local infrastructure (Jason's DF): agents register the
 * services they provide, search for providers, and subscribe to be told of them. Subscribers
 * receive {@code tell provider(Agent, "service")} from the agent {@code df}, as in Jason.
 */
final class DirectoryFacilitator {
    private final Map<String, Set<String>> services = new LinkedHashMap<>();
    private final Map<String, Set<String>> subscribers = new LinkedHashMap<>();
    private final Consumer<Message> send;
    private int serial;

    DirectoryFacilitator(Consumer<Message> send) {
        this.send = send;
    }

    synchronized void register(String agent, String service) {
        services.computeIfAbsent(agent, a -> new LinkedHashSet<>()).add(service);
        for (String s : subscribers.getOrDefault(service, Set.of())) {
            tell(s, agent, service);
        }
    }

    synchronized void deregister(String agent, String service) {
        Set<String> of = services.get(agent);
        if (of != null) {
            of.remove(service);
        }
    }

    /** {@return the providers, in the order of a Java hash set of names (Jason's answer order)} */
    synchronized Collection<String> search(String service) {
        var found = new HashSet<String>();
        services.forEach((agent, of) -> {
            if (of.contains(service)) {
                found.add(agent);
            }
        });
        return found;
    }

    synchronized void subscribe(String agent, String service) {
        subscribers.computeIfAbsent(service, s -> new LinkedHashSet<>()).add(agent);
        for (String provider : search(service)) {
            tell(agent, provider, service);
        }
    }

    private void tell(String receiver, String provider, String service) {
        send.accept(new Message("df" + (++serial), "df", receiver, "tell",
                Literal.of("provider", Literal.atom(provider), new StringTerm(service)), null));
    }
}
