package jacabot.cartago.remote;

/**
 * The frames after the handshake, each a type byte and its fields ({@link Wire} values).
 *
 * <pre>
 * client → node   JOIN  workspace, agent          then any number of
 *                 EXEC  opId, target (0 any | 1 id value | 2 name), operation, argc, args...
 *                 QUIT
 * node → client   JOINED ok, message              then, in any order,
 *                 OUTCOME opId, 1, n, (index, value)*  |  opId, 0, message, reason functor or null, reason args
 *                 EVENT kind, artifact id, fields of the kind (see ArtifactObserver)
 * </pre>
 */
final class Frames {
    static final int JOIN = 'J';
    static final int EXEC = 'X';
    static final int QUIT = 'Q';
    static final int JOINED = 'j';
    static final int OUTCOME = 'o';
    static final int EVENT = 'e';

    static final int FOCUSED = 'F';
    static final int ADDED = 'A';
    static final int UPDATED = 'U';
    static final int REMOVED = 'R';
    static final int SIGNALLED = 'S';
    static final int ENDED = 'E';

    static final int TARGET_ANY = 0;
    static final int TARGET_ID = 1;
    static final int TARGET_NAME = 2;

    private Frames() {
    }
}
