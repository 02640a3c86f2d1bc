package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import dev.predmon.support.RealLogs;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Models, or an abstraction, that do not fit the log: a real robot's recording judged with the simulator's models
 * (forgetting {@code --models}). The log names a location and commands of a known component the models never saw,
 * and thousands of pose values no rule maps. predmon says so in one line with the likely fix and gives no verdict
 * (exit 3, bad input), after the unmapped messages grouped by command in at most about ten lines; it used to print a
 * line per pose value and then a verdict ("best match: depleted: FAULTY", "property held").
 */
class ModelsThatDoNotFitTest {

    private static final Path SHIPPED = Path.of("models");

    @TempDir
    Path tmp;

    /** A nominal run, then the fetch robot's traffic: poses, a location the thesis's tree has not, its arm. */
    private Path fetchRobotLog() throws Exception {
        Records fetch = new Records().at(100);
        for (int i = 0; i < 300; i++) {
            String pose = String.format(Locale.ROOT, "%.6f;%.6f", -6 + i * 0.01, 0.5 - i * 0.001);
            fetch.call("/GetCurrentPoseClient", "/GoToComponent", "GoTo", "getCurrentPose", "", pose);
        }
        fetch.goTo("user").status("user", 1);
        for (int i = 0; i < 20; i++) {
            fetch.call("/IsFetchedClient", "/ArmServiceComponent", "ArmService", "hasGrasped", "", "27503");
        }
        return Files.writeString(tmp.resolve("fetch.log"), HandRuns.recharge().text() + fetch.text());
    }

    private static void noVerdict(Cli r, String what) {
        assertEquals(ExitCodes.BAD_INPUT, r.code(), what + ": " + r.out() + r.err());
        List<String> err = r.err().strip().lines().toList();
        assertTrue(err.size() <= 12, what + " printed " + err.size() + " lines:\n" + r.err());
        String last = err.get(err.size() - 1);
        assertTrue(last.contains("GoTo/getCurrentPose") && last.contains("location 'user'")
                && last.contains("the models do not fit this log: no verdict; try --abstraction scope-fetch"), last);
        assertTrue(err.stream().anyMatch(l -> l.contains("GoTo/getCurrentPose (600 messages): no rule for this "
                + "command")), "grouped by command: " + r.err());
        assertTrue(!r.out().contains("best match") && !r.out().contains(" hold")
                && !r.out().contains("matches scenario"), what + " gave a verdict: " + r.out());
    }

    /**
     * The lines of {@code err} about the log: without the models' scorecard, which watch prints at its start (a few
     * lines for each property the models forecast, whatever the log).
     */
    private static long ofTheLog(String err) {
        return err.strip().lines().filter(l -> !l.startsWith("predmon: scorecard of ") && !l.startsWith("predmon:   "))
                .count();
    }

    @Test
    void everyVerdictCommandSaysTheModelsDoNotFitAndGivesNone() throws Exception {
        Path log = fetchRobotLog();
        String models = SHIPPED.toString();
        noVerdict(Cli.run("classify", "--log", log.toString(), "--models", models), "classify");
        noVerdict(Cli.run("explain", "--log", log.toString(), "--models", models), "explain");
        noVerdict(Cli.run("verify", "--log", log.toString(), "--models", models, "--scenario", "recharge"), "verify");
        noVerdict(Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", models), "watch");
    }

    @Test
    @Timeout(30)
    void whileFollowingItIsSaidOnceAndTheStopGivesNoVerdict() throws Exception {
        Path log = fetchRobotLog();
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", SHIPPED.toString(), "--poll-ms", "5");
        FleetWatchTest.await(() -> w.err().toString().contains("do not fit this log: still watching"), "says it while following");
        w.stop();
        assertEquals(ExitCodes.BAD_INPUT, w.code().get(), w.out() + "\n" + w.err());
        String err = w.err().toString();
        assertEquals(1, err.lines().filter(l -> l.contains("still watching")).count(), err);
        assertTrue(ofTheLog(err) <= 12, err);
        assertTrue(w.out().toString().contains("; no verdict"), w.out().toString());
    }

    @Test
    void learnGroupsWhatItLeavesOutAndNamesTheAbstractionThatFits() throws Exception {
        Path recordings = Files.createDirectories(tmp.resolve("recordings"));
        Files.move(fetchRobotLog(), recordings.resolve("fetch.log"));
        Cli r = Cli.run("learn", "--logs", recordings.toString(), "--models", tmp.resolve("m").toString());
        List<String> err = r.err().strip().lines().toList();
        assertTrue(err.size() <= 14, "learn printed " + err.size() + " lines:\n" + r.err());
        assertTrue(r.err().contains("try --abstraction scope-fetch"), r.err());
    }

    /** The case as it was found: a real recording, and the shipped models of the simulator. */
    @Test
    void aRealRecordingWithTheSimulatorsModels() {
        Path real = RealLogs.DIR.resolve("ral-sim/succbase.txt");
        Assumptions.assumeTrue(Files.isRegularFile(real), "the real recordings are not here");
        for (String command : List.of("classify", "watch")) {
            Cli r = command.equals("watch") ? Cli.run("watch", "--no-follow", "--log", real.toString())
                    : Cli.run(command, "--log", real.toString());
            assertEquals(ExitCodes.BAD_INPUT, r.code(), command + ": " + r.out());
            // about ten lines of unmapped messages, and for watch the models' scorecard at its start
            assertTrue(ofTheLog(r.err()) <= 12, r.err());
            assertTrue(r.err().strip().endsWith("try --abstraction scope-fetch, with models learned with it (--models)"),
                    r.err());
        }
    }
}
