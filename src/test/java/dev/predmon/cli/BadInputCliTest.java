package dev.predmon.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import picocli.CommandLine.Command;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every kind of bad input, through the command line: a one-line message on stderr that names the file and says
 * what is wrong, the documented exit code, and never a stack trace unless {@code --verbose} asks for one.
 */
class BadInputCliTest {

    @TempDir
    Path tmp;
    Path logs;
    Path models;

    @BeforeEach
    void learn() throws Exception {
        logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(logs, models, "recharge");
    }

    private Cli watch(Path log, String... more) {
        List<String> args = new ArrayList<>(List.of("watch", "--log", log.toString(), "--models",
                models.toString(), "--no-follow"));
        args.addAll(List.of(more));
        return Cli.run(args.toArray(String[]::new));
    }

    /** stderr is exactly one line, naming {@code file} and containing {@code what}; no stack trace. */
    private static void oneLine(Cli r, Path file, String what) {
        List<String> lines = r.err().strip().lines().toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).contains(file.toString()), "names " + file + ": " + r.err());
        assertTrue(lines.get(0).contains(what), "says '" + what + "': " + r.err());
    }

    @Test
    void aDirectoryInsteadOfALog() {
        Cli r = watch(logs);
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        oneLine(r, logs, "is a directory");
    }

    private static byte[] garbage() {
        byte[] bytes = new byte[4096];
        new Random(7).nextBytes(bytes);
        return bytes;
    }

    /** Bytes that are not UTF-8 inside a record: the record is reported at its line, the rest is processed. */
    @Test
    void aLogWithBinaryBytesIsReadToTheEndWithItsProblemsLocated() throws Exception {
        List<String> lines = HandRuns.recharge().text().lines().toList();
        int cut = 7 * 5 + 3; // inside the sixth record, after its From and To fields
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        bytes.write((String.join("\n", lines.subList(0, cut)) + "\n").getBytes(StandardCharsets.UTF_8));
        bytes.write(garbage());
        bytes.write(("\n" + String.join("\n", lines.subList(cut, lines.size())) + "\n").getBytes(StandardCharsets.UTF_8));
        Path log = Files.write(tmp.resolve("binary.log"), bytes.toByteArray());
        Cli r = watch(log);
        assertEquals(ExitCodes.NO_MATCH, r.code(), r.err()); // the record lost to the bytes: no model has its trace
        assertTrue(r.out().contains("end of " + log), r.out());
        assertFalse(r.err().isBlank(), "the broken record is reported");
        for (String line : r.err().strip().lines().toList()) {
            assertTrue(line.matches(Pattern.quote(log.toString()) + ":\\d+: error: .*"), "file:line: " + line);
        }
    }

    /** Files that cannot be read are named, with the reason in words: no Java class name in any message. */
    @Test
    void filesThatCannotBeReadAreNamedWithoutJavaClassNames() throws Exception {
        Path run = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        Path missing = tmp.resolve("missing.json");
        Cli abstraction = watch(run, "--abstraction", missing.toString());
        assertEquals(ExitCodes.BAD_INPUT, abstraction.code());
        oneLine(abstraction, missing, missing + ": cannot read: no such file");
        Path dir = Files.createDirectories(tmp.resolve("dir.json"));
        Cli directory = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString(), "--abstraction", dir.toString());
        assertEquals(ExitCodes.BAD_INPUT, directory.code());
        oneLine(directory, dir, dir + ": cannot read: is a directory");
        Path scenarioJson = logs.resolve("recharge/scenario.json");
        Files.delete(scenarioJson);
        Files.createDirectory(scenarioJson);
        Cli scenario = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(ExitCodes.BAD_INPUT, scenario.code());
        oneLine(scenario, scenarioJson, "scenario.json");
        for (Cli r : List.of(abstraction, directory, scenario)) {
            assertFalse(r.err().matches("(?s).*\\b(java|javax|sun)\\.[a-z]+\\..*|.*Exception.*"), r.err());
        }
    }

    @Test
    void aDotThatIsNotAMealyMachine() throws Exception {
        Files.writeString(models.resolve("depleted.dot"), "digraph g { s0 -> s1 [label=\"a\"]; }");
        Cli r = watch(Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text()));
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        oneLine(r, models.resolve("depleted.dot"), "not a Mealy machine");
    }

    @Test
    void aTruncatedIndex() throws Exception {
        Path index = models.resolve("index.json");
        String text = Files.readString(index);
        Files.writeString(index, text.substring(0, text.length() / 3));
        Cli r = watch(Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text()));
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        oneLine(r, index, "not a predmon model index");
        assertTrue(r.err().contains(index + ":"), "with a line number: " + r.err());
    }

    @Test
    void modelsLearnedWithAnotherAbstraction() throws Exception {
        String json = new String(Abstraction.class.getResourceAsStream("default-abstraction.json").readAllBytes(),
                StandardCharsets.UTF_8).replace("\"charging_station\"", "\"dock\"");
        Path other = Files.writeString(tmp.resolve("other-abstraction.json"), json);
        Cli r = watch(Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text()),
                "--abstraction", other.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        oneLine(r, models.resolve("index.json"), "learned with another version of abstraction 'thesis-tables-4.1-4.2-bands-5.2'");
        assertTrue(r.err().contains("they differ at locations.charging_station, locations.dock"), r.err());
        assertTrue(r.err().contains("omit --abstraction to use the one they were learned with ("
                + models.resolve("abstraction.json") + ")"), r.err());
        assertEquals(1, r.err().split("'thesis-tables-4.1-4.2-bands-5.2'", -1).length - 1, "the name once: " + r.err());
    }

    @Test
    void aModelWhoseAlphabetDoesNotMatch() throws Exception {
        Path index = models.resolve("index.json");
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode root = (ObjectNode) mapper.readTree(index.toFile());
        ((ArrayNode) root.get("alphabet")).remove(0);
        mapper.writeValue(index.toFile(), root);
        Cli r = watch(Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text()));
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        oneLine(r, index, "alphabet does not match");
    }

    @Test
    void aScenarioDirectoryWithNoLogs() throws Exception {
        Path empty = Files.createDirectories(logs.resolve("empty"));
        Files.writeString(empty.resolve("scenario.json"), "{\"faulty\": false, \"description\": \"nothing\"}");
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        oneLine(r, empty, "no *.log files");
    }

    @Test
    void conflictingSamplesAreSplitAndNamed() throws Exception {
        Path conflicting = tmp.resolve("conflicting");
        Records atKitchen = new Records().level(80).isAt("kitchen", true);
        Records notAtKitchen = new Records().level(80).isAt("kitchen", false);
        CliEndToEndTest.scenario(conflicting, "split", false, atKitchen.text(), notAtKitchen.text());
        Cli r = Cli.run("learn", "--logs", conflicting.toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        String split = r.out().lines().filter(l -> l.strip().startsWith("split:")).findFirst().orElseThrow(
                () -> new AssertionError("no split line: " + r.out()));
        assertTrue(split.contains("split-1.log") && split.contains("split-2.log"), split);
        assertFalse(r.err().contains("Exception"), r.err());
    }

    @Test
    void allScenariosNominalLearnsAndWatchSaysItCanNeverWarn() throws Exception {
        Path nominal = tmp.resolve("nominal");
        CliEndToEndTest.scenario(nominal, "recharge", false, HandRuns.recharge().text());
        Cli learn = Cli.run("learn", "--logs", nominal.toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, learn.code(), learn.err());
        assertTrue(learn.err().contains("'watch' can never warn"), learn.err());
        Cli r = watch(Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text()));
        // the only (nominal) model drops out, and the property is violated with no warning: a missed run
        assertEquals(ExitCodes.UNWARNED_VIOLATION, r.code(), r.err());
        assertTrue(r.err().contains("no warning can ever be raised"), r.err());
    }

    @Test
    void verbosePrintsTheStackTraceOfBadInput() {
        Cli quiet = watch(logs);
        assertFalse(quiet.err().contains("\tat "), quiet.err());
        Cli r = watch(logs, "--verbose");
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertTrue(r.err().lines().findFirst().orElseThrow().contains("is a directory"), r.err());
        assertTrue(r.err().contains("BadInputException") && r.err().contains("\tat dev.predmon.cli.WatchCommand"),
                r.err());
    }

    /** A command that fails the way a bug would, registered next to the real ones. */
    @Command(name = "boom")
    static final class Boom implements Callable<Integer> {
        @Override
        public Integer call() {
            throw new IllegalStateException("a bug");
        }
    }

    static Cli withBoom(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.addSubcommand(new CommandLine(new Boom()));
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute(args);
        return new Cli(code, out.toString(), err.toString());
    }

    @Test
    void anInternalErrorIsExit4AndVerboseShowsWhere() {
        Cli r = withBoom("boom");
        assertEquals(ExitCodes.INTERNAL, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("internal error") && r.err().contains("a bug") && r.err().contains("--verbose"),
                r.err());
        Cli verbose = withBoom("--verbose", "boom");
        assertEquals(ExitCodes.INTERNAL, verbose.code());
        assertTrue(verbose.err().contains("\tat dev.predmon.cli.BadInputCliTest$Boom.call"), verbose.err());
    }
}
