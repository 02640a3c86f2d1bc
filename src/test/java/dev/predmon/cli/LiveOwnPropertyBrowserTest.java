package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import dev.predmon.support.LiveWatch;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The live page's headline, big number and chart with models where more than the battery has a forecast: an absence
 * ("navigation never aborts", no-abort) learned from training runs whose way to the charging station is blocked. On a
 * run whose navigation aborts (its battery far above the floor), {@code watch --http}'s {@code /status} names the
 * battery as the forecast's own property by its id and no-abort as violated, {@code /metrics} says the same, and the
 * page, in headless Chromium, headlines no-abort under a red light: never "RECOVERED" or "the property held" (the
 * battery's words), its number and chart the battery's, named so, with the line where no-abort was violated. Skipped,
 * with a message, without Chromium (the {@code /status} and {@code /metrics} checks run first).
 */
class LiveOwnPropertyBrowserTest {

    @TempDir
    static Path tmp;
    static Path models;
    static Path aborted;
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();

    @BeforeAll
    static void learn() throws Exception {
        Path train = tmp.resolve("train");
        simulate(train, "direct", "100", "10");
        simulate(train, "recharge", "1100", "5", "--aborts", "1", "--abort-on", "station");
        simulate(train, "depleted", "2100", "4");
        models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", train.toString(), "--models", models.toString());
        assertEquals(0, learned.code(), learned.err());
        assertTrue(learned.out().contains("no-abort: violated in 9 of 19 runs"), learned.out());
        simulate(tmp.resolve("test"), "recharge", "6000", "1", "--aborts", "1", "--abort-on", "station");
        aborted = tmp.resolve("test/recharge/recharge-6000.log");
    }

    private static void simulate(Path dir, String scenario, String seed, String runs, String... more) {
        List<String> args = new ArrayList<>(List.of("simulate", "--scenario", scenario, "--seed", seed, "--runs", runs,
                "--out-dir", dir.resolve(scenario).toString()));
        args.addAll(List.of(more));
        Cli r = Cli.run(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.err());
    }

    /** The value of the series of {@code /metrics} whose line holds every one of {@code parts}. */
    private static String sample(String metrics, String name, String... parts) {
        return metrics.lines().filter(l -> l.startsWith(name + "{") && List.of(parts).stream().allMatch(l::contains))
                .map(l -> l.substring(l.lastIndexOf(' ') + 1)).findFirst().orElse("absent");
    }

    private static JsonNode property(JsonNode tile, String id) {
        for (JsonNode p : tile.get("properties")) {
            if (p.get("property").asText().equals(id)) {
                return p;
            }
        }
        throw new AssertionError("no property " + id + " in " + tile);
    }

    @Test
    @Timeout(240)
    void anAbortedRunHeadlinesNoAbortAndTheBatteryChartStaysTheBatterys() throws Exception {
        // the truth, from the same models without the page: no-abort warned, then violated; the battery held
        Cli truth = Cli.run("watch", "--models", models.toString(), "--json", "--no-follow", "--log",
                aborted.toString());
        List<JsonNode> events = truth.jsonLines();
        assertTrue(events.stream().anyMatch(e -> e.path("event").asText().equals("violation")
                && e.path("property").asText().equals("no-abort")), truth.out());
        assertFalse(events.stream().anyMatch(e -> e.path("event").asText().equals("violation")
                && e.path("property").asText().equals("battery")), "the battery holds: " + truth.out());

        try (LiveWatch watch = LiveWatch.start("--log", aborted.toString(), "--models", models.toString(),
                "--stale-after", "600")) {
            JsonNode tile = null;
            long deadline = System.nanoTime() + 60_000_000_000L;
            while (tile == null || !tile.path("violated").toString().contains("no-abort")) {
                assertTrue(System.nanoTime() < deadline, "no-abort never violated in /status: " + tile);
                Thread.sleep(100);
                tile = watch.status().get("logs").get(0);
            }
            assertEquals("battery", tile.get("propertyId").asText(), "the forecast's own property, by its id");
            assertEquals("violation", tile.get("state").asText(), tile.toString());
            assertEquals("red", tile.get("light").asText());
            assertEquals("[\"no-abort\"]", tile.get("violated").toString());
            assertEquals("no-abort", tile.get("worst").get("property").asText());
            assertEquals("violated", property(tile, "no-abort").get("state").asText());
            assertEquals("forecast", property(tile, "no-abort").get("model").asText(), "the absence has a forecast");
            assertEquals("holds", property(tile, "battery").get("verdict").asText());

            String metrics = watch.metrics();
            assertEquals("1.0", sample(metrics, "predmon_state", "state=\"violation\""), metrics);
            assertEquals("0.0", sample(metrics, "predmon_state", "state=\"ok\""), metrics);
            assertEquals("1.0", sample(metrics, "predmon_property_state", "property=\"no-abort\"",
                    "state=\"violated\""), metrics);
            assertEquals("1.0", sample(metrics, "predmon_property_violations_total", "property=\"no-abort\""),
                    metrics);
            assertEquals("0.0", sample(metrics, "predmon_property_state", "property=\"battery\"",
                    "state=\"violated\""), metrics);

            HeadlessChromium.Page page = watch.open(TABS, "the live page's own property is not tested in a browser");
            page.await("document.querySelector('article.tile .verdict').textContent.length > 0"
                    + " && document.querySelectorAll('article.tile li.prop').length > 1", "the tile and its lights",
                    30);
            page.screenshot(Path.of("target", "live-own-property.png"));
            assertEquals("light red", page.eval("document.querySelector('article.tile header .light').className"));
            String verdict = page.eval("document.querySelector('article.tile .verdict').textContent");
            assertTrue(verdict.startsWith("VIOLATED: no-abort \u2014 line ")
                    && verdict.contains("GoTo/getStatus reply 3"), verdict);
            assertFalse(verdict.contains("RECOVERED") || verdict.contains("the property held"), verdict);
            assertEquals("navigation never aborts",
                    page.eval("document.querySelector('article.tile .status .property').textContent"));
            // the big number: the battery's value, named as the battery's
            assertEquals("battery", page.eval("document.querySelector('article.tile .value-now .value-of')"
                    + ".textContent"));
            // the chart: the battery's readings, named, and the line where no-abort was violated
            assertEquals("battery", page.eval("document.querySelector('article.tile svg.plot text.series-name')"
                    + ".textContent"));
            String chart = page.eval("document.querySelector('article.tile svg.plot').getAttribute('aria-label')");
            assertTrue(chart.startsWith("battery (battery level >= 20% (thesis 3.3.1)) over time")
                    && chart.contains("; no-abort violated at "), chart);
            String marks = page.eval("[...document.querySelectorAll('article.tile svg.plot text')]"
                    + ".map(t => t.textContent).join('|')");
            assertTrue(marks.contains("no-abort violated"), marks);
            assertFalse(marks.contains("no-abort warning") || marks.contains("no-abort violation"),
                    "no battery mark labelled no-abort: " + marks);
            String whole = page.eval("document.querySelector('article.tile').textContent");
            assertFalse(whole.contains("RECOVERED"), whole);
            // the last events: no-abort's warning in its own words, not at a battery value it does not have
            String warned = page.eval("[...document.querySelectorAll('article.tile .events li.warning')]"
                    + ".map(l => l.textContent).join('|')");
            assertTrue(warned.contains("WARNING of no-abort: 'navigation never aborts' (no-abort): P(violation) 0."),
                    warned);
            assertFalse(warned.contains("unknown"), warned);
        }
    }
}
