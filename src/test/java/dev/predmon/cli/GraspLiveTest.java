package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.live.RobotNames;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * One voice in the live view: a robot whose grasp was retried past its limit, its battery far above the floor, is a
 * violation in {@code /status} and {@code /metrics}, and its tile's headline names grasp-in-time; the battery is one
 * property among the others, holding.
 */
class GraspLiveTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();
    private final HttpClient http = HttpClient.newHttpClient();

    @TempDir
    Path dir;

    private String get(URI url, String path) throws Exception {
        return http.send(HttpRequest.newBuilder(url.resolve(path)).build(), HttpResponse.BodyHandlers.ofString())
                .body();
    }

    /** The value of the series of {@code /metrics} whose line holds every one of {@code parts}. */
    private static String sample(String metrics, String name, String... parts) {
        return metrics.lines().filter(l -> l.startsWith(name + "{") && List.of(parts).stream().allMatch(l::contains))
                .map(l -> l.substring(l.lastIndexOf(' ') + 1)).findFirst().orElse("absent");
    }

    @Test
    @Timeout(180)
    void statusMetricsAndTileNameGraspInTimeViolatedAndTheBatteryHolding() throws Exception {
        Path log = GraspVoiceTest.simulated(dir);
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofMinutes(10), RobotNames.pattern("{file}"),
                List.of())) {
            scene.follow(log);
            JsonNode tile = JSON.readTree(get(scene.url(), "/status")).get("logs").get(0);
            assertEquals("violation", tile.get("state").asText(), tile.toString());
            assertEquals("red", tile.get("light").asText());
            assertEquals("grasp-in-time", tile.get("worst").get("property").asText());
            assertEquals("violated", tile.get("worst").get("state").asText());
            assertEquals("[\"grasp-in-time\"]", tile.get("violated").toString());
            assertEquals("[]", tile.get("warned").toString());
            // the battery's own state, as /status gave it before: it holds, and the models match the run
            assertEquals("ok", tile.get("forecastState").asText());
            JsonNode battery = null;
            for (JsonNode p : tile.get("properties")) {
                battery = p.get("property").asText().equals("battery") ? p : battery;
            }
            assertEquals("holds", battery.get("state").asText(), tile.get("properties").toString());
            assertEquals("holds", battery.get("verdict").asText());

            String metrics = get(scene.url(), "/metrics");
            assertEquals("1.0", sample(metrics, "predmon_state", "state=\"violation\""), metrics);
            assertEquals("0.0", sample(metrics, "predmon_state", "state=\"ok\""), metrics);
            assertEquals("1.0", sample(metrics, "predmon_property_state", "property=\"grasp-in-time\"",
                    "state=\"violated\""), metrics);
            assertEquals("1.0", sample(metrics, "predmon_property_state", "property=\"battery\"", "state=\"holds\""),
                    metrics);

            HeadlessChromium.Page page = TABS.open(scene.url(), "the live page is not tested in a browser");
            page.await("document.querySelectorAll('article.tile li.prop').length === 5",
                    "the tile never showed its five lights", 30);
            page.screenshot(Path.of("target", "live-grasp.png"));
            String headline = page.eval("document.querySelector('article.tile .verdict').textContent");
            assertTrue(headline.startsWith("VIOLATED: grasp-in-time \u2014 line ")
                    && headline.contains("8 closeHand attempts since line "), headline);
            assertEquals("a grasp succeeds within 8 attempts",
                    page.eval("document.querySelector('article.tile .status .property').textContent"));
            assertEquals("light red", page.eval("document.querySelector('article.tile header .light').className"));
            // the big number is the battery's, named as such
            String big = page.eval("document.querySelector('article.tile .value-now').textContent");
            assertTrue(big.startsWith("battery") && big.endsWith("%"), big);
            String lights = page.eval("[...document.querySelectorAll('article.tile li.prop')]"
                    + ".map(l => l.dataset.property + ' ' + l.dataset.state).join(', ')");
            assertTrue(lights.startsWith("grasp-in-time violated, battery holds"), lights);
            // the chart: the battery's readings, named, and where grasp-in-time was violated
            String chart = page.eval("document.querySelector('article.tile svg.plot').getAttribute('aria-label')");
            assertTrue(chart.startsWith("battery (battery level >= 20% (thesis 3.3.1)) over time")
                    && chart.contains("; grasp-in-time violated at t="), chart);
            assertEquals("grasp-in-time violated", page.eval("[...document.querySelectorAll('article.tile svg.plot "
                    + "text.label-violation')].map(t => t.textContent).join('|')"));

            // a second run in the same log: the grasp run is an earlier run, red, that says what it violated
            Path again = dir.resolve("again.log");
            Cli second = Cli.run("simulate", "--scenario", "direct", "--seed", "4", "--out", again.toString());
            assertEquals(0, second.code(), second.err());
            Path both = Files.writeString(dir.resolve("both.log"), Files.readString(log) + Files.readString(again));
            scene.follow(both);
            JsonNode earlier = null;
            for (JsonNode t : JSON.readTree(get(scene.url(), "/status")).get("logs")) {
                earlier = t.get("log").asText().equals(both.toString()) ? t.get("earlierRuns").get(0) : earlier;
            }
            assertEquals("violation", earlier.get("state").asText(), String.valueOf(earlier));
            assertEquals("[\"grasp-in-time\"]", earlier.get("violated").toString());
            String shown = "[...document.querySelectorAll('article.tile')].map(t => (t.querySelector('.runs li') "
                    + "|| {}).textContent || '').join('')";
            page.await(shown + ".includes('run 0')", "the earlier run never showed", 30);
            assertTrue(page.eval(shown).startsWith("run 0 (line 1): grasp-in-time violated; battery no warning, held"),
                    page.eval(shown));
        }
    }
}
