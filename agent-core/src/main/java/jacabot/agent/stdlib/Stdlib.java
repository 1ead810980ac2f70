package jacabot.agent.stdlib;

import jacabot.agent.semantics.InternalAction;
import java.util.LinkedHashMap;
import java.util.Map;

/** The standard internal actions, registered explicitly by name (no class-path scanning). */
public final class Stdlib {
    private Stdlib() {
    }

    /** {@return a fresh map from action name (e.g. {@code .print}) to implementation} */
    public static Map<String, InternalAction> defaults() {
        var map = new LinkedHashMap<String, InternalAction>();
        put(map, new Abolish());
        put(map, new Fork());
        put(map, new ListPlans());
        put(map, new ListRules());
        put(map, new SetAdd(false));
        put(map, new SetAdd(true));
        put(map, new CollectionCreate("set"));
        put(map, new SetRemove());
        for (SetOperation.Kind k : SetOperation.Kind.values()) {
            put(map, new SetOperation(k));
        }
        put(map, new CollectionToList(false));
        put(map, new CollectionToList(true));
        for (String family : new String[] {"set", "queue", "map"}) {
            put(map, new CollectionClear(family));
            put(map, new CollectionCopy(family));
        }
        put(map, new CollectionCreate("map"));
        put(map, new MapPut());
        put(map, new MapGet());
        put(map, new MapRemove());
        put(map, new MapEntries(true));
        put(map, new MapEntries(false));
        put(map, new QueueCreate());
        put(map, new QueueAdd(false));
        put(map, new QueueAdd(true));
        put(map, new QueueTake(false));
        put(map, new QueueTake(true));
        put(map, new Join());
        put(map, new Type());
        put(map, new At());
        put(map, new IntentionIa());
        put(map, new Log());
        put(map, new AddAnnot());
        put(map, new AddNestedSource());
        put(map, new AddPlan());
        put(map, new AllNames());
        put(map, AssertBelief.asserta());
        put(map, AssertBelief.assertz());
        put(map, new Belief());
        put(map, new Broadcast());
        put(map, new Concat());
        put(map, new Count());
        put(map, CopyTerm.copyTerm());
        put(map, new Clone());
        put(map, new CreateAgent());
        put(map, new KillAgent());
        put(map, new Namespace());
        put(map, new Include());
        for (DfAction.Kind k : DfAction.Kind.values()) {
            put(map, new DfAction(k));
        }
        put(map, new ListFiles());
        put(map, new PlanLabel());
        put(map, new RelevantRules());
        put(map, new CurrentIntention());
        put(map, new DateIa());
        put(map, new Eval());
        put(map, new Delete());
        put(map, new Desire());
        put(map, new Difference());
        put(map, new DropAllDesires());
        put(map, new DropAllEvents());
        put(map, new DropAllIntentions());
        put(map, new DropDesire());
        put(map, new DropEvent());
        put(map, new DropIntention());
        put(map, new Empty());
        put(map, new Fail());
        put(map, new FailGoal());
        put(map, new Findall());
        put(map, new Foreach());
        put(map, new IfThenElse());
        put(map, new Intend());
        put(map, new Intersection());
        put(map, new IsAtom());
        put(map, new IsGround());
        put(map, new IsList());
        put(map, new IsLiteral());
        put(map, new IsNumber());
        put(map, new IsString());
        put(map, new IsStructure());
        put(map, new Length());
        put(map, new Loop());
        put(map, ChangeCase.lower());
        put(map, Extremum.max());
        put(map, new Member());
        put(map, Extremum.min());
        put(map, new MyName());
        put(map, new NanoTime());
        put(map, new Nth());
        put(map, Sublists.prefix());
        put(map, new Print());
        put(map, new Printf());
        put(map, new Println());
        put(map, new Puts());
        put(map, new Random());
        put(map, new Range());
        put(map, new RelevantPlans());
        put(map, new RelevantPlan());
        put(map, new GetSrcInfo());
        put(map, new SaveAgent());
        put(map, new DropFutureIntention());
        put(map, new RemovePlan());
        put(map, new RemoveSourceAnnot());
        put(map, CopyTerm.renameApart());
        put(map, new Replace());
        put(map, new Resume());
        put(map, new Reverse());
        put(map, new Send());
        put(map, new SetRandomSeed());
        put(map, new Setof());
        put(map, new Shuffle());
        put(map, new Sort());
        put(map, new StopMAS());
        put(map, Sublists.sublist());
        put(map, new Substring());
        put(map, Sublists.suffix());
        put(map, new SucceedGoal());
        put(map, new Suspend());
        put(map, new Suspended());
        put(map, new SystemTime());
        put(map, new Term2string());
        put(map, new Time());
        put(map, new Union());
        put(map, ChangeCase.upper());
        put(map, new Version());
        put(map, new Wait());
        put(map, new Verbose());
        put(map, new Perceive());
        put(map, new PrintUnifier());
        put(map, new Signal());
        put(map, new InternalActionCheck());
        put(map, new Done());
        return map;
    }

    private static void put(Map<String, InternalAction> map, DefaultInternalAction ia) {
        map.put(ia.name(), ia);
    }
}
