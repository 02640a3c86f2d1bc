package dev.predmon.cli;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link Main#commandLine(String[])} builds only the subcommand that runs: it must behave exactly as the full
 * command line of the tests does, in help, usage errors and the inherited {@code --verbose}.
 */
class SubcommandStartTest {

    private static List<String> names() {
        return PredmonCommand.SUBCOMMANDS.stream()
                .map(c -> c.getAnnotation(CommandLine.Command.class).name()).toList();
    }

    @Test
    void aSubcommandNameBuildsThatSubcommandOnly() {
        assertEquals(11, names().size());
        for (String name : names()) {
            CommandLine cl = Main.commandLine(new String[] {name, "--help"});
            assertEquals(List.of(name), List.copyOf(cl.getSubcommands().keySet()));
            assertTrue(cl.getSubcommands().get(name).getCommandSpec().findOption("--verbose") != null,
                    name + " inherits --verbose");
        }
    }

    @Test
    void anythingElseBuildsEverySubcommand() {
        for (String[] args : List.of(new String[0], new String[] {"--help"}, new String[] {"--version"},
                new String[] {"nosuch"}, new String[] {"clasify", "--log", "x"}, new String[] {"--verbose", "classify"},
                new String[] {"CLASSIFY"})) {
            assertEquals(names(), List.copyOf(Main.commandLine(args).getSubcommands().keySet()), String.join(" ", args));
        }
    }

    /** Help, usage errors and failures print the same, with the same exit code, from either command line. */
    @Test
    void itPrintsWhatTheFullCommandLinePrints() {
        for (String name : names()) {
            for (String[] args : List.of(new String[] {name, "--help"}, new String[] {name, "--no-such-option"},
                    new String[] {name, "--version"})) {
                assertEquals(run(Main.commandLine(), args), run(Main.commandLine(args), args), String.join(" ", args));
            }
        }
        String[] failing = {"classify", "--log", "no-such.log", "--models", "no-such-models", "--verbose"};
        String slim = run(Main.commandLine(failing), failing);
        assertTrue(slim.contains("\tat "), "--verbose prints the stack trace: " + slim);
        // the stack traces differ only in the test's own line numbers
        assertEquals(withoutFrames(run(Main.commandLine(), failing)), withoutFrames(slim));
    }

    private static String withoutFrames(String text) {
        return text.replaceAll("(?m)^\tat .*\n", "");
    }

    private static String run(CommandLine cl, String[] args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute(args);
        return code + "\n" + out + "\n" + err;
    }
}
