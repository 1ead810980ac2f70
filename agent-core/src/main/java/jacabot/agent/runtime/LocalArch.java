package jacabot.agent.runtime;

import jacabot.agent.parser.AslParser;
import jacabot.agent.semantics.Clock;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.AgentArch;
import jacabot.agent.semantics.Message;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import java.util.Collection;
import java.util.List;

/** The architecture of an agent in a {@link LocalMAS}: environment, mail, console and clock. */
public class LocalArch implements AgentArch {
    private final LocalMAS mas;
    private final String name;

    public LocalArch(LocalMAS mas, String name) {
        this.mas = mas;
        this.name = name;
    }

    public String name() {
        return name;
    }

    public LocalMAS mas() {
        return mas;
    }

    @Override
    public List<Literal> perceive() {
        return mas.environment().percepts(name);
    }

    @Override
    public void act(ActionExec action, Agent agent) {
        mas.environment().execute(name, action, agent);
    }

    @Override
    public boolean sendMessage(Message m) {
        return mas.deliver(m);
    }

    @Override
    public List<String> agentNames() {
        return mas.agentNames();
    }

    @Override
    public void console(String line) {
        mas.console(line);
    }

    @Override
    public void stopMAS() {
        mas.stop();
    }

    @Override
    public Clock clock() {
        return mas.clock();
    }

    @Override
    public void wake() {
        mas.wake(name);
    }

    @Override
    public boolean dfRegister(String agent, String service) {
        mas.df().register(agent, service);
        return true;
    }

    @Override
    public boolean dfDeregister(String agent, String service) {
        mas.df().deregister(agent, service);
        return true;
    }

    @Override
    public Collection<String> dfSearch(String service) {
        return mas.df().search(service);
    }

    @Override
    public boolean dfSubscribe(String agent, String service) {
        mas.df().subscribe(agent, service);
        return true;
    }

    @Override
    public void stopMAS(long deadlineMs) {
        mas.stopIn(deadlineMs);
    }

    @Override
    public String createAgent(String agentName, AgentProgram program, AslParser parser) {
        return mas.spawn(agentName, program, parser);
    }

    @Override
    public String cloneAgent(String agentName, AgentProgram program, AslParser parser) {
        return mas.spawnCopy(agentName, program, parser);
    }

    @Override
    public boolean killAgent(String agentName) {
        return mas.kill(agentName);
    }
}
