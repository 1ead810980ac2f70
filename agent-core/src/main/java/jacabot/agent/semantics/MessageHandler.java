package jacabot.agent.semantics;

import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

/** ProcMsg: how a received message changes beliefs, goals or a waiting ask. */
final class MessageHandler {
    private final Agent ag;
    private final ReasoningCycle rc;
    /** {@code source(S)} by sender: a stream of messages from one agent shares one annotation. */
    private final Map<String, Literal> sources = new HashMap<>();

    MessageHandler(Agent ag, ReasoningCycle rc) {
        this.ag = ag;
        this.rc = rc;
    }

    void handle(Message m) {
        Circumstance c = ag.circumstance();
        if (m.inReplyTo() != null) {
            Intention waiting = c.removePendingIntention(m.inReplyTo());
            if (waiting != null) {
                answerAsk(waiting, m);
                return;
            }
        }
        Literal source = sources.computeIfAbsent(m.sender(),
                s -> Literal.of("source", Literal.atom(s.equals(ag.name()) ? "self" : s)));
        Term content = m.content();
        switch (m.performative()) {
            case "tell":
                for (Literal l : literals(content)) {
                    Literal added = ag.addBelief(nested(l, source), false);
                    if (added != null) {
                        c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, added), null));
                    }
                }
                break;
            case "untell":
                for (Literal l : literals(content)) {
                    Literal removed = ag.removeBelief(l.addAnnot(source), ag.newUnifier());
                    if (removed != null) {
                        c.addEvent(new Event(new Trigger(Trigger.Op.DEL, Trigger.Type.BELIEF, removed), null));
                    }
                }
                break;
            case "tellHow":
                // plans (as text or plan terms) told by the sender, with it as their source
                for (Term t : content instanceof ListTerm list ? list.elements() : List.of(content)) {
                    try {
                        jacabot.agent.syntax.Plan p = t instanceof jacabot.agent.syntax.StringTerm st ? ag.parser().parsePlan(st.value())
                                : t instanceof jacabot.agent.syntax.PlanTerm pt ? pt.toPlan() : null;
                        if (p != null) {
                            ag.planLibrary().add(p, source.args().get(0), false);
                        }
                    } catch (jacabot.agent.parser.AslSyntaxException | IllegalArgumentException e) {
                        ag.warn("Error in the plan told by " + m.sender() + ": " + e.getMessage());
                    }
                }
                break;
            case "untellHow":
                for (Term t : content instanceof ListTerm list ? list.elements() : List.of(content)) {
                    ag.planLibrary().removeSource(t instanceof Literal l ? l.functor() : t.toString(), source.args().get(0));
                }
                break;
            case "signal":
                // an event without a belief, as Jason's signal
                if (content instanceof Literal l) {
                    c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.BELIEF, l.addAnnot(source)), null));
                }
                break;
            case "achieve":
                if (content instanceof Literal l) {
                    c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, l.addAnnot(source)), null));
                }
                break;
            case "unachieve":
                if (content instanceof Literal l) {
                    for (Intention i : ag.intentionsFor(l, ag.newUnifier())) {
                        ag.dropIntention(i);
                    }
                }
                break;
            case "askOne":
            case "askAll":
                answer(m, content);
                break;
            default:
                ag.warn("Unknown performative '" + m.performative() + "' in " + m);
        }
    }

    /**
     * Jason's {@code .add_nested_source}: the content's own sources go inside the sender's,
     * {@code b[source(c)]} from a becomes {@code b[source(a)[source(c)]]}.
     */
    static Literal nested(Literal l, Literal source) {
        var sources = new ArrayList<Term>();
        var others = new ArrayList<Term>();
        for (Term a : l.annots()) {
            (a instanceof Literal al && al.functor().equals("source") && al.arity() == 1 ? sources : others).add(a);
        }
        if (sources.isEmpty()) {
            return l.addAnnot(source);
        }
        others.add(source.withAnnots(sources));
        return l.withAnnots(others);
    }

    /** The answer to an ask: the belief found, with its annotations but {@code source(self)} (Jason's bel_no_source_self). */
    private Term answerFor(Unifier u, Term content) {
        Term a = u.apply(content);
        if (a instanceof Literal l && l.isGround()) {
            Literal fact = ag.beliefBase().fact(l);
            if (fact != null) {
                return l.withAnnots(fact.annots().stream().filter(x -> !x.equals(Literal.SOURCE_SELF)).toList());
            }
        }
        return a;
    }

    private static List<Literal> literals(Term content) {
        var out = new ArrayList<Literal>();
        if (content instanceof Literal l) {
            out.add(l);
        } else if (content instanceof ListTerm list) {
            for (Term t : list.elements()) {
                if (t instanceof Literal l) {
                    out.add(l);
                }
            }
        }
        return out;
    }

    /** Answers askOne with the first solution (untell when none) and askAll with the list. */
    private void answer(Message m, Term content) {
        Iterator<Unifier> it = ag.solver().solve(content, ag.newUnifier());
        Message reply;
        if (m.performative().equals("askOne")) {
            reply = it.hasNext()
                    ? new Message(ag.nextMessageId(), ag.name(), m.sender(), "tell", answerFor(it.next(), content), m.id())
                    : new Message(ag.nextMessageId(), ag.name(), m.sender(), "untell", content, m.id());
        } else {
            var answers = new ArrayList<Term>();
            while (it.hasNext()) {
                answers.add(answerFor(it.next(), content));
            }
            reply = new Message(ag.nextMessageId(), ag.name(), m.sender(), "tell", ListTerm.of(answers), m.id());
        }
        ag.arch().sendMessage(reply);
    }

    /** A sync ask got its answer: bind the fourth argument of the {@code .send} and resume. */
    private void answerAsk(Intention i, Message m) {
        IntendedMeans im = i.peek();
        Literal send = (Literal) im.currentStep().term();
        Term answer = m.content();
        Literal from = Literal.of("source", Literal.atom(m.sender()));
        if (m.performative().equals("untell") && send.arity() > 1 && send.arg(1).toString().equals("askOne")) {
            answer = Literal.FALSE;
        } else if (answer instanceof Literal l) {
            answer = nested(l, from);
        } else if (answer instanceof ListTerm list) {
            var items = new ArrayList<Term>();
            for (Term t : list.elements()) {
                items.add(t instanceof Literal l ? nested(l, from) : t);
            }
            answer = ListTerm.of(items);
        }
        if (im.unifier().unifies(send.arg(3), answer)) {
            rc.removeActionReQueue(i);
        } else {
            rc.generateGoalDeletion(i, ReasoningCycle.errorAnnots("ask_failed",
                    "reply of an ask message ('" + answer + "') does not unify with fourth argument of .send"));
        }
    }
}
