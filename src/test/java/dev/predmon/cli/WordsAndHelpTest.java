package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * One vocabulary across watch, explain, classify and verify (a model that stops matching is "eliminated" in each),
 * and help texts that say what the program does by default.
 */
class WordsAndHelpTest {

    @TempDir
    Path tmp;
    Path logs;
    Path models;
    Path depleted;

    @BeforeEach
    void learn() throws Exception {
        logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(logs, models, "recharge");
        depleted = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
    }

    /** The nominal model stops matching the depleted run: every command says so with the same word. */
    @Test
    void everyCommandSaysEliminated() {
        String m = models.toString();
        String log = depleted.toString();
        List<Cli> runs = List.of(Cli.run("watch", "--no-follow", "--eliminations", "--log", log, "--models", m),
                Cli.run("explain", "--log", log, "--models", m), Cli.run("classify", "--log", log, "--models", m),
                Cli.run("verify", "--log", log, "--models", m, "--scenario", "recharge"));
        for (Cli r : runs) {
            String out = r.out();
            assertTrue(out.matches("(?s).*recharge.*eliminated.*") || out.matches("(?s).*eliminated: recharge.*"),
                    out);
            for (String other : List.of("deleted", "case 3", "case 2", "stopped at")) {
                assertFalse(out.contains(other), "'" + other + "' in " + out);
            }
        }
        assertTrue(Cli.run("classify", "--log", log, "--models", m, "--json").out().contains("\"eliminated\":true"));
    }

    @Test
    void predmonAlonePrintsUsageAndExits2() {
        Cli r = Cli.run();
        assertEquals(ExitCodes.USAGE, r.code());
        assertTrue(r.err().contains("Usage: predmon") && r.err().contains("watch"), r.err());
        assertEquals("", r.out());
    }

    @Test
    void helpTextsMatchTheDefaults() {
        assertTrue(Cli.run("learn", "--help").out().contains("*.txt"), "learn takes a folder of recordings");
        String watch = Cli.run("watch", "--help").out();
        int forecast = watch.indexOf("forecast");
        int match = watch.indexOf("--rule match");
        assertTrue(forecast >= 0 && match > forecast, "the default rule first: " + watch);
        assertTrue(watch.replaceAll("\\s+", " ").contains("(see docs/watch.md)"), watch);
        assertTrue(watch.contains("Exit 6"), watch);
        // evaluate takes --logs in both layouts learn takes, and its help says so
        String evaluate = Cli.run("evaluate", "--help").out().replaceAll("\\s+", " ");
        assertTrue(evaluate.contains("one folder per scenario") && evaluate.contains("a folder of recordings not "
                + "sorted into scenarios"), evaluate);
    }

    /** Two logs per scenario, 100 folds asked: each log is a fold, and the note says so. */
    @Test
    void foldsBeyondTheLogsSayWhatWasDone() throws Exception {
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text(), HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text(), HandRuns.depleted().text());
        Cli r = Cli.run("evaluate", "--logs", logs.toString(), "--folds", "100", "--quiet");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(r.err().contains("predmon: note: 4 logs: leave-one-out (asked for 100 folds)"), r.err());
        assertTrue(r.out().startsWith("4-fold cross-validation"), r.out());
        assertFalse(r.out().contains("100-fold"), r.out());
    }
}
