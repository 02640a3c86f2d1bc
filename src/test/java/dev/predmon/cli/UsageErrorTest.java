package dev.predmon.cli;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A usage error is its line and where the help is, not the whole help after it: 30 to 65 lines of help scrolled the
 * line that says what was wrong out of sight.
 */
class UsageErrorTest {

    private static final List<String> COMMANDS = List.of("learn", "watch", "verify", "classify", "explain", "simulate",
            "evaluate", "export-samples", "bench", "demo", "abstraction");

    @Test
    void anUnknownOptionIsOneLineAndWhereTheHelpIs() {
        for (String command : COMMANDS) {
            Cli r = Cli.run(command, "--no-such-option");
            assertEquals(ExitCodes.USAGE, r.code(), command);
            List<String> lines = r.err().strip().lines().toList();
            assertTrue(lines.size() <= 3, command + " printed " + lines.size() + " lines:\n" + r.err());
            assertTrue(lines.get(0).startsWith("predmon: "), r.err());
            assertEquals("see 'predmon " + command + " --help'", lines.get(lines.size() - 1), r.err());
            assertFalse(r.err().contains("Usage:"), r.err());
            assertEquals("", r.out(), command);
        }
    }

    /** A value that would make watch look for new lines without a pause, a core spent on nothing. */
    @Test
    void aPollIntervalOutsideOneMillisecondToAMinuteIsRefused() {
        for (String bad : List.of("-1", "0", "60001")) {
            Cli r = Cli.run("watch", "--log", "x.log", "--polling", "--poll-ms", bad);
            assertEquals(ExitCodes.USAGE, r.code(), bad + ": " + r.err());
            assertEquals("predmon: --poll-ms must be from 1 to 60000 milliseconds, got " + bad,
                    r.err().lines().findFirst().orElse(""));
        }
    }

    @Test
    void aMissingOrImpossibleValueAndAnUnknownCommandToo() {
        Cli missing = Cli.run("watch");
        assertEquals(ExitCodes.USAGE, missing.code());
        assertEquals(List.of("predmon: Missing required option: '--log=FILE'", "see 'predmon watch --help'"),
                missing.err().strip().lines().toList());

        Cli negative = Cli.run("classify", "--log", "x.log", "--tolerance", "-1");
        assertEquals(ExitCodes.USAGE, negative.code());
        assertEquals(2, negative.err().strip().lines().count(), negative.err());
        assertTrue(negative.err().contains("--tolerance must be at least 0"), negative.err());
        Cli oldName = Cli.run("classify", "--log", "x.log", "--threshold", "-1");
        assertEquals(ExitCodes.USAGE, oldName.code(), "the option's earlier name is still taken");
        assertTrue(oldName.err().contains("--threshold must be at least 0"), oldName.err());
        assertFalse(Cli.run("classify", "--help").out().contains("--threshold"), "and not shown in the help");

        // learn's spelling, in watch: said, not hidden behind "Missing required option: '--log=FILE'"
        Cli plural = Cli.run("watch", "--logs", "robots", "--models", "models");
        assertEquals(ExitCodes.USAGE, plural.code());
        assertEquals(List.of("predmon: unknown option '--logs': 'predmon watch' spells it '--log'",
                "see 'predmon watch --help'"), plural.err().strip().lines().toList());

        Cli misspelt = Cli.run("clasify", "--log", "x.log");
        assertEquals(ExitCodes.USAGE, misspelt.code());
        assertTrue(misspelt.err().contains("classify"), "suggests the command: " + misspelt.err());
        assertTrue(misspelt.err().strip().endsWith("see 'predmon --help'"), misspelt.err());
        assertTrue(misspelt.err().strip().lines().count() <= 4, misspelt.err());
    }
}
