package dev.predmon.cli;

import dev.predmon.Terminal;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Log values and file names are anyone's bytes. An ESC, a BEL, a NUL or a carriage return that reaches the terminal
 * can erase the WARNING line or hide what came before it, and a newline in a file name forges a line of predmon's
 * own. In text output each shows as a visible escape.
 */
class ControlCharactersTest {

    /** ESC [1A ESC [2K: cursor up one line and erase it, the sequence that hides a WARNING printed just before. */
    private static final String ERASE_LINE_ABOVE = "\u001b[1A\u001b[2K";

    @TempDir
    Path tmp;
    Path models;

    @BeforeEach
    void learn() throws Exception {
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(tmp.resolve("logs"), models, "recharge");
    }

    /** Nothing a terminal acts on: no control character but the line ends. */
    private static void plain(String text) {
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            assertTrue(c == '\n' || (c >= 0x20 && c != 0x7f), "a raw control character " + (int) c + " in: " + text);
        }
    }

    @Test
    void escBelAndNulFromLogValuesAreEscapedOnStderrAndStdout() throws Exception {
        // A faulty run, then an interface message whose protocol and command carry control characters.
        String hostile = HandRuns.depleted().text() + "95.0\tDEBUG\tCommand intercepted:\n"
                + "  From      : /client\n  To        : /server\n  Protocol  : Evil" + ERASE_LINE_ABOVE + "\n"
                + "  Command   : ri\u0007ng\u0000now\rx\n  Arguments : \n  Reply     : \n";
        Path log = Files.writeString(tmp.resolve("run" + ERASE_LINE_ABOVE + ".log"), hostile);
        Cli r = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", models.toString());
        assertEquals(ExitCodes.WARNING, r.code(), r.err());
        plain(r.out());
        plain(r.err());
        assertTrue(r.err().contains("Evil\\x1b[1A\\x1b[2K/ri\\x07ng\\x00now\\rx"), r.err());
        assertTrue(r.out().contains("end of " + tmp.resolve("run\\x1b[1A\\x1b[2K.log")), r.out());
        assertTrue(r.out().contains("WARNING"), r.out());
    }

    @Test
    void aNewlineInAFileNameForgesNoLine() throws Exception {
        Path fleet = Files.createDirectories(tmp.resolve("robots"));
        Files.writeString(fleet.resolve("robot-1.log"), HandRuns.recharge().text());
        String forged = "x.log\nWARNING: the run can only be faulty scenario depleted\n.log";
        Files.writeString(fleet.resolve(forged), HandRuns.recharge().text());
        Cli r = Cli.run("watch", "--no-follow", "--log", fleet.toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        plain(r.out());
        for (String line : r.out().split("\n", 0)) {
            assertTrue(line.startsWith(fleet.toString()) || line.startsWith("end of " + fleet), "a forged line: " + line);
        }
        assertFalse(r.out().lines().anyMatch(l -> l.startsWith("WARNING")), r.out());
        assertTrue(r.out().contains("x.log\\nWARNING: the run can only be faulty scenario depleted\\n.log"), r.out());
    }

    /**
     * A hook's {@code PREDMON_LOG} is one line too: the documented recipe {@code echo "warning $PREDMON_LOG" | yarp
     * write ...} would otherwise send the robot two lines, and an ESC to whatever shows them.
     */
    @Test
    void aHooksLogNameHasItsNewlineAndEscEscaped() throws Exception {
        Path log = Files.writeString(tmp.resolve("run\nWARNING\u001b[2K.log"), HandRuns.depleted().text());
        Path got = tmp.resolve("got");
        Cli r = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", models.toString(),
                "--on-warning", "printf '%s' \"$PREDMON_LOG\" > '" + got + "'");
        assertEquals(ExitCodes.WARNING, r.code(), r.err());
        assertEquals(tmp.resolve("run\\nWARNING\\x1b[2K.log").toString(), Files.readString(got));
    }

    /**
     * A property's name is the abstraction file's text: one with a right-to-left override is escaped in the end
     * summary's verdict lines as in the violation line, so that it cannot reorder what the summary says.
     */
    @Test
    void aPropertyNameWithARightToLeftOverrideIsEscapedInTheEndSummary() throws Exception {
        Cli show = Cli.run("abstraction", "show", "thesis");
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        com.fasterxml.jackson.databind.node.ObjectNode a =
                (com.fasterxml.jackson.databind.node.ObjectNode) json.readTree(show.out());
        for (com.fasterxml.jackson.databind.JsonNode p : a.get("properties")) {
            if (p.get("id").asText().equals("no-abort")) {
                ((com.fasterxml.jackson.databind.node.ObjectNode) p).put("name", "navigation \u202eerongi never aborts");
            }
        }
        Path abstraction = Files.writeString(tmp.resolve("rlo.json"), json.writeValueAsString(a));
        Cli r = Cli.run("watch", "--no-follow", "--log", "src/test/resources/property/navigation-aborts.txt",
                "--models", models.toString(), "--abstraction", abstraction.toString());
        assertFalse(r.out().contains("\u202e"), "no raw override: " + r.out());
        assertTrue(r.out().contains("VIOLATION of 'navigation \\u202eerongi never aborts'"), r.out());
        assertTrue(r.out().contains("\n  no-abort (navigation \\u202eerongi never aborts): violated at line 157"),
                r.out());
    }

    @Test
    void escapesShowWhatWasThereAndLeaveOtherTextAlone() {
        assertEquals("a\\x1bb\\x07c\\x00d\\re\\nf\\tg\\x7fh\\x9bi", Terminal.line("a\u001bb\u0007c\u0000d\re\nf\tg\u007fh\u009bi"));
        assertEquals("\\u202egnp.exe", Terminal.line("\u202egnp.exe"), "a right-to-left override reorders the name");
        String plain = "robots/robot-1.log:12: error: Ünïcödé, 50%, C:\\path";
        assertEquals(plain, Terminal.line(plain));
    }
}
