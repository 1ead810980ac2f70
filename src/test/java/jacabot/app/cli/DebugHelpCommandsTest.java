package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.Inspector;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * How to debug a failing run, as the tools' own help and the README show it (find the moment,
 * break there, change a plan, what if): each step is there, and every command written there is
 * one the launcher accepts as written (its subcommand and options; running them is the business
 * of the debugger's, the what-if's and the replay command's own tests).
 */
class DebugHelpCommandsTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    /** A command in a help text: {@code jacabot SUBCOMMAND ...} up to the end of its line, a {@code ;} or a closing tag. */
    private static final Pattern COMMAND = Pattern.compile("(?:build/install/jacabot/bin/)?jacabot ((?:replay|experiment|plot) [^;<`\\n]+)");

    @Test
    void theReplayCommandsHelpShowsTheFourStepsWithCommandsThatParse() {
        String[] r = CliRun.run("replay", "--help");
        assertEquals("0", r[0], r[2]);
        String help = r[1].replaceAll("\\s+", " ");
        for (String step : List.of("Find the moment", "Break there", "Change a plan", "What if")) {
            assertTrue(help.contains(step), step + " in:\n" + r[1]);
        }
        // the footer, not the usage's synopsis; its placeholders given a value as a user would
        String footer = r[1].substring(r[1].indexOf("Debugging a failing run")).replace("NAME-SEED", "navigation-3")
                .replace("NAME", "navigation");
        assertParse(commands(footer), 4, r[1]);
    }

    @Test
    void thePagesHelpShowsTheFourStepsWithCommandsThatParse() throws Exception {
        String html;
        try (InputStream in = Inspector.class.getResourceAsStream("help.html")) {
            html = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        for (String step : List.of("Find the moment", "Break there", "Change a plan", "What if")) {
            assertTrue(html.contains(step), step);
        }
        assertParse(commands(html), 5, html);
    }

    @Test
    void theReadmesCommandsParse() throws Exception {
        String readme = Files.readString(ROOT.resolve("README.md"));
        assertTrue(readme.contains("**Debug a failing run.**"), "the README has the debugging step");
        assertParse(commands(readme), 6, readme);
    }

    /** {@return the commands in {@code text}, as arguments (single quotes removed as a shell does)} */
    private static List<List<String>> commands(String text) {
        var out = new ArrayList<List<String>>();
        Matcher m = COMMAND.matcher(text);
        while (m.find()) {
            var args = new ArrayList<String>();
            Matcher word = Pattern.compile("'([^']*)'|(\\S+)").matcher(m.group(1).trim());
            while (word.find()) {
                args.add(word.group(1) != null ? word.group(1) : word.group(2));
            }
            out.add(args);
        }
        return out;
    }

    private static void assertParse(List<List<String>> commands, int atLeast, String where) {
        assertTrue(commands.size() >= atLeast, "commands found: " + commands + " in\n" + where);
        for (List<String> args : commands) {
            String[] a = args.toArray(String[]::new);
            assertDoesNotThrow(() -> JacabotCommand.commandLine(a).parseArgs(a), "the launcher accepts: jacabot " + String.join(" ", args));
        }
    }
}
