package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * {@code .list_files(Folder[, Regex], Files)}: the paths of the files below Folder (searched
 * recursively) whose name matches Regex; a folder that does not exist has none.
 */
final class ListFiles extends DefaultInternalAction {
    ListFiles() {
        super(".list_files", 2, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String pattern = args.length == 3 ? text(args[1]) : ".*";
        var found = new ArrayList<Term>();
        collect(new File(text(args[0])), pattern, found);
        return un.unifies(args[args.length - 1], listOf(found));
    }

    private static void collect(File folder, String pattern, List<Term> found) {
        File[] files = folder.listFiles();
        if (files == null) {
            return;
        }
        Arrays.sort(files); // the file system's order is not stable; sorted, runs are repeatable
        for (File f : files) {
            if (f.isFile() && f.getName().matches(pattern)) {
                found.add(new StringTerm(f.getPath()));
            } else if (f.isDirectory()) {
                collect(f, pattern, found);
            }
        }
    }
}
