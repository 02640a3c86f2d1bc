package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch --config FILE}: every setting from one file, the command line over it, and each mistake in it one line
 * naming the file and line.
 */
class WatchConfigTest {

    private static final Path MODELS = Path.of("models").toAbsolutePath();

    @TempDir
    Path dir;
    Path depleted;

    @BeforeEach
    void logs() throws Exception {
        depleted = Files.writeString(dir.resolve("depleted.log"), FleetWatchTest.run(Scenario.DEPLETED, 9001));
    }

    private Path config(String... lines) throws Exception {
        return Files.writeString(dir.resolve("watch.conf"), String.join("\n", lines) + "\n");
    }

    @Test
    void everySettingComesFromTheFileAsFromTheCommandLine() throws Exception {
        Path conf = config("\uFEFF# an editor's byte-order mark, a comment, then a blank line", "",
                "log = " + depleted, "  models=" + MODELS + "  ", "no-follow = true", "json = TRUE", "rule = match");
        Cli fromFile = Cli.run("watch", "--config", conf.toString());
        Cli fromFlags = Cli.run("watch", "--log", depleted.toString(), "--models", MODELS.toString(), "--no-follow",
                "--json", "--rule", "match");
        assertEquals(ExitCodes.WARNING, fromFile.code(), fromFile.err());
        String when = ",\"wallTime\":\"[^\"]*\""; // when each event was written: not the same in two runs
        assertEquals(fromFlags.out().replaceAll(when, ""), fromFile.out().replaceAll(when, ""), "the same events");
        assertEquals("match", Cli.firstEvent(fromFile.jsonLines(), "end").orElseThrow().get("rule").asText());
    }

    @Test
    void theCommandLineOverridesTheFile() throws Exception {
        Path conf = config("log = " + dir.resolve("absent.log"), "models = " + dir.resolve("no-models"),
                "no-follow = true", "json = true");
        Cli c = Cli.run("watch", "--config", conf.toString(), "--log", depleted.toString(), "--models",
                MODELS.toString(), "--json=false");
        assertEquals(ExitCodes.WARNING, c.code(), c.err());
        assertTrue(c.out().contains("end of " + depleted + ": "), "text, not JSON: " + c.out());
    }

    /** log may be repeated, as --log on the command line; given on the command line, it replaces the file's list. */
    @Test
    void severalLogsFromTheFile() throws Exception {
        Path recharge = Files.writeString(dir.resolve("recharge.log"), FleetWatchTest.run(Scenario.RECHARGE, 9002));
        Path conf = config("log = " + depleted, "log = " + recharge, "models = " + MODELS, "no-follow = true",
                "json = true");
        List<JsonNode> ends = Cli.run("watch", "--config", conf.toString()).jsonLines().stream()
                .filter(e -> e.get("event").asText().equals("end")).toList();
        assertEquals(List.of(depleted.toString(), recharge.toString()), ends.stream().map(e -> e.get("log").asText())
                .toList());
        Cli one = Cli.run("watch", "--config", conf.toString(), "--log", recharge.toString());
        assertEquals(1, one.jsonLines().stream().filter(e -> e.get("event").asText().equals("end")).count());
        assertEquals(ExitCodes.OK, one.code(), one.err());
    }

    /** A hook command's $VARIABLES are the shell's: the file hands them over untouched. */
    @Test
    void aHookCommandKeepsItsShellVariables() throws Exception {
        Path heard = dir.resolve("heard.txt");
        Path conf = config("log = " + depleted, "models = " + MODELS, "no-follow = true",
                "on-warning = echo \"${PREDMON_EVENT} $PREDMON_LOG $$\" > " + heard);
        Cli c = Cli.run("watch", "--config", conf.toString());
        assertEquals(ExitCodes.WARNING, c.code(), c.err());
        String line = Files.readString(heard).strip();
        assertTrue(line.matches("warning " + java.util.regex.Pattern.quote(depleted.toString()) + " [0-9]+"), line);
    }

    private Cli refused(int code, String... lines) throws Exception {
        Cli c = Cli.run("watch", "--config", config(lines).toString());
        assertEquals(code, c.code(), c.err());
        assertEquals("", c.out());
        return c;
    }

    /** The first line of stderr. */
    private static String first(Cli c) {
        return c.err().lines().findFirst().orElse("");
    }

    @Test
    void eachMistakeIsOneLineNamingTheFileAndLine() throws Exception {
        String at = dir.resolve("watch.conf") + ":";
        assertEquals("predmon: " + at + "2: unknown setting 'modls'; the settings are ",
                first(refused(ExitCodes.USAGE, "log = a.log", "modls = models")).replaceFirst("are .*", "are "));
        assertEquals("predmon: " + at + "3: Invalid value for option '--poll-ms': 'often' is not a long",
                first(refused(ExitCodes.USAGE, "log = a.log", "# poll", "poll-ms = often")));
        assertEquals("predmon: " + at + "1: --stale-after must be a positive number of seconds, got -1.0",
                first(refused(ExitCodes.USAGE, "stale-after = -1", "log = a.log")));
        assertEquals("predmon: " + at + "2: 'json' is a switch: true or false, got 'yes'",
                first(refused(ExitCodes.USAGE, "log = a.log", "json = yes")));
        assertEquals("predmon: " + at + "2: 'models' is set again (first on line 1); it takes one value",
                first(refused(ExitCodes.USAGE, "models = a", "models = b", "log = a.log")));
        assertEquals("predmon: " + at + "1: expected 'name = value' (a long option of 'predmon watch' without its "
                + "dashes), got 'tail -F robot.log'", first(refused(ExitCodes.USAGE, "tail -F robot.log")));
        assertEquals("predmon: " + at + "1: write the option's name without its dashes: 'log'",
                first(refused(ExitCodes.USAGE, "--log = a.log")));
        assertEquals("predmon: " + at + "1: 'http' has no value", first(refused(ExitCodes.USAGE, "http =")));
        assertEquals("predmon: " + at + "1: unknown setting 'config'; the settings are ",
                first(refused(ExitCodes.USAGE, "config = other.conf")).replaceFirst("are .*", "are "));
    }

    @Test
    void aFileThatCannotBeReadIsBadInput() throws Exception {
        Path absent = dir.resolve("absent.conf");
        Cli c = Cli.run("watch", "--config", absent.toString());
        assertEquals(ExitCodes.BAD_INPUT, c.code());
        assertEquals("predmon: " + absent + ": cannot read: no such file\n", c.err());
        Path binary = Files.write(dir.resolve("binary.conf"), new byte[] {'l', 'o', 'g', '=', (byte) 0xff, '\n'});
        c = Cli.run("watch", "--config", binary.toString());
        assertEquals(ExitCodes.BAD_INPUT, c.code());
        assertEquals("predmon: " + binary + ": not UTF-8 text: not a settings file\n", c.err());
        // a device without end: read up to the limit, not until the heap is gone
        c = Cli.run("watch", "--config", "/dev/zero");
        assertEquals(ExitCodes.BAD_INPUT, c.code());
        assertEquals("predmon: /dev/zero: larger than 1 MiB: not a settings file\n", c.err());
    }

    /**
     * A value all in quotes would reach the option with its quotes: a hook's shell would look for a command named
     * {@code "echo ..."} and fail with exit 127 at the first warning. Refused when the file is read; quotes inside a
     * value (a command's own arguments) are the value's.
     */
    @Test
    void aQuotedValueIsRefusedWhenTheFileIsRead() throws Exception {
        String at = dir.resolve("watch.conf") + ":";
        assertEquals("predmon: " + at + "2: 'on-warning' is quoted: values are taken as they are, quotes included; "
                + "write it without the quotes around it",
                first(refused(ExitCodes.USAGE, "log = a.log", "on-warning = \"echo warning $PREDMON_LOG\"")));
        assertEquals("predmon: " + at + "1: 'name' is quoted: values are taken as they are, quotes included; "
                + "write it without the quotes around it", first(refused(ExitCodes.USAGE, "name = 'r1'")));
        CommandLine watch = new CommandLine(WatchCommand.class);
        ConfigFile inner = ConfigFile.read(config("log = a.log", "on-warning = \"/opt/my tools/alert\" \"$PREDMON_LOG\""),
                watch.getCommandSpec());
        assertEquals("\"/opt/my tools/alert\" \"$$PREDMON_LOG\"",
                inner.defaultValue(watch.getCommandSpec().findOption("--on-warning")));
    }

    /** The example in docs/ names only settings watch has, with values it takes. */
    @Test
    void theDocumentedExampleIsValid() throws Exception {
        CommandLine watch = new CommandLine(WatchCommand.class);
        ConfigFile example = ConfigFile.read(Path.of("docs/predmon-watch.conf"), watch.getCommandSpec());
        assertEquals("/var/log/robot/monitor.log", example.defaultValue(watch.getCommandSpec().findOption("--log")));
        assertTrue(example.defaultValue(watch.getCommandSpec().findOption("--on-warning")).contains("$$PREDMON_"));
    }
}
