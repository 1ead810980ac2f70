package jacabot.agent.semantics;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
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
    private final AskRuleVars askVars;
    private static final Var ANONYMOUS_SOURCE = new Var("_");

    /** {@code source(S)} by sender: a stream of messages from one agent shares one annotation. */
    private final Map<String, Literal> sources = new HashMap<>();

    /**
     * An ask the belief base cannot answer but a {@code +?} plan may: the test goal runs in an
     * intention of its own, and its failure answers {@code false}; other failures of a
     * {@code kqml_received} goal are printed (as Jason's kqmlPlans).
     */
    private static final List<Plan> KQML_PLANS = parsePlans(
            "@kqmlReceivedAskOne +!kqml_received(Sender, askOne, NS::Content, MsgId) <- ?NS::Content; .send(Sender, tell, NS::Content, MsgId).",
            "@kqmlReceivedAskOneFailed -!kqml_received(Sender, askOne, NS::Content, MsgId)[error(test_goal_failed)]"
                    + " <- .send(Sender, untell, NS::Content, MsgId).",
            "@kqmlError -!kqml_received(_, _, _, _)[error(Id), error_msg(Msg)] <- .print(\"Communication error -- \", Id, \": \", Msg).");

    MessageHandler(Agent ag, ReasoningCycle rc) {
        this.ag = ag;
        this.rc = rc;
        this.askVars = new AskRuleVars(ag);
        ag.planLibrary().setKqmlPlans(KQML_PLANS);
    }

    private static List<Plan> parsePlans(String... texts) {
        var parser = new AslParser();
        var out = new ArrayList<Plan>();
        for (String t : texts) {
            try {
                Plan p = parser.parsePlan(t);
                out.add(p.withLabel(p.label().addAnnot(Literal.of("source", Literal.atom("kqmlPlans")))));
            } catch (AslSyntaxException e) {
                throw new IllegalStateException(e);
            }
        }
        return out;
    }

    /**
     * ProcMsg: a message becomes the goal {@code +!kqml_received(Sender, Performative, Content,
     * MsgId)} when the agent has plans of its own for it (Jason's customisation of performatives)
     * or when it is an ask; what the agent's plans leave is handled by {@link #handleByDefault}
     * when the goal is selected (as Jason's kqmlPlans, which come after the agent's own plans).
     * Other messages are handled at once. (Jason handles only tell and achieve at once; its
     * other performatives go through plans, which lets a tell overtake an earlier untell.)
     */
    void handle(Message m) {
        Circumstance c = ag.circumstance();
        if (m.inReplyTo() != null) {
            Intention waiting = c.removePendingIntention(m.inReplyTo());
            if (waiting != null) {
                answerAsk(waiting, m);
                return;
            }
            if (m.inReplyTo().startsWith(Message.SYNC_ASK_PREFIX)) {
                return; // the answer to a synchronous ask that timed out is dropped, as Jason does
            }
        }
        String sender = m.sender().equals(ag.name()) ? "self" : m.sender();
        // asks wait for their turn among the events (and may need a +? plan); other messages are
        // handled at once, in the order they came, unless the agent customises kqml_received
        boolean direct = !m.performative().startsWith("ask") && !hasOwnKqmlPlans();
        if (direct) {
            perform(sender, m.performative(), m.content(), m, null);
        } else {
            Literal received = Literal.of("kqml_received", Literal.atom(sender), Literal.atom(m.performative()),
                    m.content(), Literal.atom(m.id()));
            c.addEvent(new Event(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, received), null));
        }
    }

    private static final Trigger KQML_RECEIVED = new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE,
            Literal.of("kqml_received", new Var("S"), new Var("P"),
                    new Var("C"), new Var("M")));

    /** The plan library's version when {@link #ownKqmlPlans} was found (each message asks). */
    private int kqmlPlansChecked = -1;
    private boolean ownKqmlPlans;

    private boolean hasOwnKqmlPlans() {
        PlanLibrary pl = ag.planLibrary();
        if (kqmlPlansChecked != pl.version()) {
            ownKqmlPlans = false;
            for (Plan p : pl.candidates(KQML_RECEIVED)) {
                if (!pl.isKqmlPlan(p)) {
                    ownKqmlPlans = true;
                    break;
                }
            }
            kqmlPlansChecked = pl.version();
        }
        return ownKqmlPlans;
    }

    /**
     * A {@code +!kqml_received} goal no plan of the agent's own applies to: the message is handled
     * as Jason's default plans do. {@return false for an askOne the belief base cannot answer but
     * a {@code +?} plan may: the built-in plan posting the test goal handles it}
     */
    boolean handleByDefault(Literal received) {
        if (received.arity() != 4 || !(received.arg(0) instanceof Literal s) || !(received.arg(1) instanceof Literal p)) {
            return false;
        }
        Term content = received.arg(2);
        if (p.functor().equals("askOne") || p.functor().equals("askAll")) {
            askVars.ruleQuery(content);
        }
        if (p.functor().equals("askOne") && content instanceof Literal l
                && !ag.solver().solve(l, ag.newUnifier()).hasNext()
                && ag.planLibrary().hasCandidate(new Trigger(Trigger.Op.ADD, Trigger.Type.TEST, l))) {
            return false;
        }
        perform(s.functor(), p.functor(), content, null, received.arg(3).toString());
        return true;
    }

    /**
     * Handles a message from {@code sender} ({@code self} for the agent itself); its id is the
     * original's when there is one (made only if an answer or a warning needs it), else {@code msgId}.
     */
    private void perform(String sender, String performative, Term content, Message original, String msgId) {
        Circumstance c = ag.circumstance();
        String replyTo = sender.equals("self") ? ag.name() : sender;
        Literal source = sources.get(sender);
        if (source == null) {
            source = Literal.of("source", Literal.atom(sender));
            sources.put(sender, source);
        }
        switch (performative) {
            case "tell":
                if (content instanceof Literal l) {
                    // the usual tell, one literal
                    Literal added = ag.addBelief(nested(l, source), false);
                    if (added != null) {
                        c.addBeliefEvent(Trigger.Op.ADD, added);
                    }
                    break;
                }
                for (Literal l : literals(content)) {
                    Literal added = ag.addBelief(nested(l, source), false);
                    if (added != null) {
                        c.addBeliefEvent(Trigger.Op.ADD, added);
                    }
                }
                break;
            case "untell":
                for (Literal l : literals(content)) {
                    Literal removed = ag.removeBelief(l.addAnnot(source), ag.newUnifier());
                    if (removed != null) {
                        c.addBeliefEvent(Trigger.Op.DEL, removed);
                    }
                }
                break;
            case "tellHow":
                // plans (as text or plan terms) told by the sender, with it as their source
                for (Term t : content instanceof ListTerm list ? list.elements() : List.of(content)) {
                    try {
                        Plan p = t instanceof StringTerm st ? ag.parser().parsePlan(st.value())
                                : t instanceof PlanTerm pt ? pt.toPlan() : null;
                        if (p != null) {
                            // the plan's own sources go (Jason's .remove_source_annot): the sender is its source
                            if (p.label() != null) {
                                p = p.withLabel(withoutSources(p.label()));
                            }
                            ag.planLibrary().add(p, source.args().get(0), false);
                        }
                    } catch (AslSyntaxException | IllegalArgumentException e) {
                        ag.warn("Error in the plan told by " + replyTo + ": " + e.getMessage());
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
                answer(received(replyTo, performative, content, original, msgId), content);
                break;
            case "askHow":
                answerHow(received(replyTo, performative, content, original, msgId), content);
                break;
            default:
                ag.warn("Unknown performative '" + performative + "' in " + received(replyTo, performative, content, original, msgId));
        }
    }

    /** The message as this agent answers it: from its sender to this agent. */
    private Message received(String replyTo, String performative, Term content, Message original, String msgId) {
        return new Message(original != null ? original.id() : msgId, replyTo, ag.name(), performative, content, null);
    }

    /**
     * Jason's {@code .add_nested_source}: the content's own sources go inside the sender's,
     * {@code b[source(c)]} from a becomes {@code b[source(a)[source(c)]]}.
     */
    static Literal nested(Literal l, Literal source) {
        if (l.annots().isEmpty()) {
            return l.addAnnot(source);
        }
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
    private Term answerFor(Unifier u, Term content, boolean everySolution) {
        Term a = u.apply(content);
        Literal fact = a instanceof Literal l && l.isGround() ? ag.beliefBase().fact(l) : null;
        if (a instanceof Literal l) {
            askVars.solution(l, fact, everySolution);
        }
        if (a instanceof Literal l && l.isGround()) {
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
            if (it.hasNext()) {
                reply = new Message(ag.nextMessageId(), ag.name(), m.sender(), "tell", answerFor(it.next(), content, false), m.id());
            } else {
                askVars.unanswered(content);
                reply = new Message(ag.nextMessageId(), ag.name(), m.sender(), "untell", content, m.id());
            }
        } else {
            var answers = new ArrayList<Term>();
            while (it.hasNext()) {
                answers.add(answerFor(it.next(), content, true));
            }
            reply = new Message(ag.nextMessageId(), ag.name(), m.sender(), "tell", ListTerm.of(answers), m.id());
        }
        ag.arch().sendMessage(reply);
    }

    private static Literal withoutSources(Literal l) {
        return l.withAnnots(l.annots().stream()
                .filter(a -> !(a instanceof Literal al && al.functor().equals("source") && al.arity() == 1)).toList());
    }

    /** Answers askHow with the relevant plans, as plan terms without their source (Jason's {@code .remove_source_annot}). */
    private void answerHow(Message m, Term content) {
        Trigger te = null;
        if (content instanceof TriggerTerm tt) {
            te = tt.trigger();
        } else if (content instanceof StringTerm st) {
            try {
                if (ag.parser().parseTerm("{" + st.value() + "}") instanceof TriggerTerm tt) {
                    te = tt.trigger();
                }
            } catch (AslSyntaxException e) {
                te = null;
            }
        }
        if (te == null) {
            ag.warn("The content of askHow from " + m.sender() + " is not a trigger: " + content);
            return;
        }
        var plans = new ArrayList<Term>();
        // a trigger without a source asks for the agent's own plans (Jason's .relevant_plans)
        Term asked = te.literal() instanceof Literal l && !l.hasSource() ? l.addAnnot(Literal.SOURCE_SELF) : te.literal();
        if (asked != te.literal()) {
            ag.freshVar(ANONYMOUS_SOURCE); // Jason asks with source(_), a fresh variable: its number is taken
        }
        for (Plan p : ag.planLibrary().candidates(te)) {
            if (!ag.planLibrary().isKqmlPlan(p) && ag.newUnifier().unifies(p.trigger().literal(), asked)) {
                plans.add(Renamer.renameApart(new PlanTerm(p.withLabel(withoutSources(p.label()))), ag));
            }
        }
        ag.arch().sendMessage(new Message(ag.nextMessageId(), ag.name(), m.sender(), "tellHow", ListTerm.of(plans), m.id()));
    }

    /** A sync ask got its answer: bind the fourth argument of the {@code .send} and resume. */
    private void answerAsk(Intention i, Message m) {
        IntendedMeans im = i.peek();
        Literal send = (Literal) im.currentStep().term();
        Term answer = answerTerm(send, m);
        if (im.unifier().apply(send.arg(0)) instanceof ListTerm receivers) {
            // an ask to many: the answers gather, in the order they come, until every receiver has answered
            List<Term> gathered = new ArrayList<>(Message.answersSoFar(im.unifier(), m.inReplyTo()).elements());
            gathered.add(answer);
            Message.keepAnswers(im.unifier(), m.inReplyTo(), ListTerm.of(gathered));
            if (gathered.size() < receivers.elements().size()) {
                ag.circumstance().addPendingIntention(m.inReplyTo(), Message.waitingFor(m.inReplyTo()), i);
                return;
            }
            answer = ListTerm.of(gathered);
        }
        if (im.unifier().unifies(send.arg(3), answer)) {
            rc.removeActionReQueue(i);
        } else {
            // as Jason: the .send step goes first, so the failure names the step after it (none at the plan's end)
            String message = "reply of an ask message ('" + answer + "') does not unify with fourth argument of .send ('"
                    + im.unifier().apply(send.arg(3)) + "')";
            im.removeCurrentStep();
            rc.generateGoalDeletion(i, im.currentStep() == null ? List.of() : ReasoningCycle.errorAnnots("ask_failed", message));
        }
    }

    /** {@return a reply's content as the ask's answer: false for an untold askOne, the sender as a nested source} */
    private Term answerTerm(Literal send, Message m) {
        Term answer = m.content();
        Literal from = Literal.of("source", Literal.atom(m.sender()));
        if (m.performative().equals("untell") && send.arity() > 1 && send.arg(1).toString().equals("askOne")) {
            answer = Literal.FALSE;
        } else if (answer instanceof Literal l) {
            answer = nested(l, from);
        } else if (answer instanceof ListTerm list) {
            var items = new ArrayList<Term>();
            for (Term t : list.elements()) {
                items.add(t instanceof Literal l ? nested(l, from)
                        : t instanceof PlanTerm pt && pt.label() instanceof Literal pl
                                ? new PlanTerm(pl.addAnnot(from), pt.trigger(), pt.context(), pt.body(), pt.source())
                                : t);
            }
            answer = ListTerm.of(items);
        }
        return answer;
    }
}
