package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.live.Board;
import dev.predmon.live.HttpAddress;
import dev.predmon.live.LiveServer;
import dev.predmon.live.RobotNames;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The models' own scorecard as a user meets it: {@code learn} prints it in two lines and stores it in
 * {@code forecast.json}, {@code watch} prints it once at startup, and {@code /status} carries it.
 */
class ScorecardCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Pattern FIRST = Pattern.compile("scorecard of '([^']+)' \\((\\d+)-fold cross-validation on "
            + "(\\d+) runs\\): warned (\\d+) of (\\d+) violations, (\\d+) false alarm\\(s\\) in (\\d+) safe runs, "
            + "median lead [0-9.]+ s");

    @TempDir
    static Path tmp;
    static Path models;
    static Cli learned;

    @BeforeAll
    static void learn() {
        models = tmp.resolve("models");
        learned = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
        assertEquals(0, learned.code(), learned.err());
    }

    /** The last two lines of learn's output are the scorecard, and they say what forecast.json stores. */
    @Test
    void learnPrintsTheScorecardInTwoLinesAndStoresIt() throws Exception {
        List<String> lines = learned.out().lines().toList();
        int at = lines.indexOf(lines.stream().filter(l -> l.startsWith("scorecard of 'battery")).findFirst()
                .orElseThrow());
        String first = lines.get(at);
        String second = lines.get(at + 1);
        Matcher m = FIRST.matcher(first);
        assertTrue(m.matches(), first);
        assertTrue(second.matches("  Brier score 0\\.\\d{3} vs 0\\.\\d{3} for the base rate: .+"), second);

        JsonNode file = JSON.readTree(models.resolve("forecast.json").toFile());
        JsonNode f = file.get("properties").get("battery");
        JsonNode cards = f.get("scorecards");
        assertEquals(1, cards.size(), "the battery's; no navigation missed its deadline, so it has none: " + cards);
        JsonNode c = cards.get(0);
        assertEquals("battery level >= 20% (thesis 3.3.1)", c.get("property").asText());
        assertEquals(m.group(1), c.get("property").asText());
        assertEquals(5, c.get("folds").asInt());
        // every training run is judged once, held out from the models that forecast it
        assertEquals(f.get("runs").asInt(), c.get("runs").asInt());
        assertEquals(f.get("violating").asInt(), c.get("violating").asInt());
        assertEquals(Integer.parseInt(m.group(3)), c.get("runs").asInt());
        assertEquals(Integer.parseInt(m.group(4)), c.get("warned").asInt());
        assertEquals(Integer.parseInt(m.group(5)), c.get("violating").asInt());
        assertEquals(Integer.parseInt(m.group(6)), c.get("falseAlarms").asInt());
        assertEquals(c.get("runs").asInt() - c.get("violating").asInt(), Integer.parseInt(m.group(7)));
        assertEquals("s", c.get("unit").asText());
        assertTrue(second.contains(String.format(java.util.Locale.ROOT, "%.3f vs %.3f",
                c.get("brier").asDouble(), c.get("baseBrier").asDouble())), second);
        // The simulated depleted runs drain towards the violation: the forecast sees most of them coming, early,
        // and knows more than the base rate.
        assertTrue(c.get("warned").asInt() >= c.get("violating").asInt() - 1, c.toString());
        assertTrue(c.get("medianLead").asDouble() > 2, c.toString());
        assertTrue(c.get("brier").asDouble() < c.get("baseBrier").asDouble(), c.toString());
        assertTrue(second.endsWith("the forecast knows more than how often runs violate"), second);

        // the deadline's rule says it was not validated, and why
        JsonNode rule = file.get("properties").get("navigation-in-time");
        assertFalse(rule.get("validated").asBoolean(), rule.toString());
        assertTrue(rule.get("note").asText().contains("all held"), rule.toString());
    }

    /** watch says how far to trust its models once, on stderr, before following; stdout stays the events'. */
    @Test
    void watchPrintsTheScorecardOnceAtStartup() throws Exception {
        Path a = Files.copy(Path.of("sample-logs", "direct", "direct-1.log"), tmp.resolve("a.log"));
        Path b = Files.copy(Path.of("sample-logs", "direct", "direct-2.log"), tmp.resolve("b.log"));
        Cli w = Cli.run("watch", "--no-follow", "--json", "--log", a.toString(), "--log", b.toString(),
                "--models", models.toString());
        assertEquals(0, w.code(), w.err());
        List<String> firsts = w.err().lines().filter(l -> l.startsWith("predmon: scorecard of ")).toList();
        // the battery's and the aborts' (the depleted sample runs abort their navigation): each once
        assertEquals(2, firsts.size(), "once for the fleet, not once per log: " + w.err());
        assertTrue(FIRST.matcher(firsts.get(0).substring("predmon: ".length())).matches(), firsts.get(0));
        assertTrue(w.err().contains("predmon:   Brier score "), w.err());
        assertFalse(w.out().contains("scorecard"), "stdout holds the JSON events only");
    }

    /** {@code /status} carries the scorecard with its words and whether the forecast has skill. */
    @Test
    void statusCarriesTheScorecard() throws Exception {
        Abstraction abstraction = AbstractionFiles.load(ModelStore.storedAbstraction(models).orElseThrow());
        ModelSet set = ModelStore.read(models, abstraction);
        Board board = new Board(set, abstraction, Duration.ofSeconds(10), RobotNames.byFile());
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), board)) {
            HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    server.url().resolve("/status")).build(), HttpResponse.BodyHandlers.ofString());
            JsonNode cards = JSON.readTree(r.body()).get("scorecards");
            assertEquals(2, cards.size(), "the battery's and the aborts' " + r.body());
            JsonNode c = cards.get(0);
            JsonNode stored = JSON.readTree(models.resolve("forecast.json").toFile()).get("properties")
                    .get("battery").get("scorecards").get(0);
            for (String key : List.of("property", "folds", "runs", "violating", "warned", "falseAlarms", "brier",
                    "baseBrier")) {
                assertEquals(stored.get(key), c.get(key), key);
            }
            assertTrue(c.get("skill").asBoolean(), c.toString());
            assertTrue(c.get("summary").asText().startsWith("these models warned " + stored.get("warned").asInt()
                    + " of " + stored.get("violating").asInt() + " violations in cross-validation"), c.toString());
        }
    }
}
