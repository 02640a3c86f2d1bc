package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.Scorecard;
import dev.predmon.live.RobotNames;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.simulate.Scenario;
import dev.predmon.support.HeadlessChromium;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The models' scorecard on the live page, in headless Chromium at 1920x1080: under the header in words, and, where
 * the forecast did no better than the base rate in cross-validation, the tile says so instead of showing the
 * probability as its headline. Skipped, with a message, without Chromium.
 *
 * <p>{@code docs/live-no-skill.png} is made with
 * {@code mvn -q test -Dtest=LiveScorecardBrowserTest -Dpredmon.screenshots=docs}.
 */
class LiveScorecardBrowserTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static HeadlessChromium browser;

    @TempDir
    Path dir;

    @BeforeAll
    static void startBrowser() throws Exception {
        Optional<Path> chromium = HeadlessChromium.find();
        if (chromium.isPresent()) {
            browser = HeadlessChromium.start(chromium.get(), 1920, 1080);
        }
    }

    @AfterAll
    static void stopBrowser() throws Exception {
        if (browser != null) {
            browser.close();
        }
    }

    private static Abstraction abstraction() throws Exception {
        return AbstractionFiles.load(ModelStore.storedAbstraction(ForecastModels.get()).orElseThrow());
    }

    /** Models learned from the sample logs, with their scorecard. */
    private static ModelSet models() throws Exception {
        return ModelStore.read(ForecastModels.get(), abstraction());
    }

    /** A robot part way through a recharge run: OK, with a forecast. */
    private Path robot() throws Exception {
        String recharge = FleetWatchTest.run(Scenario.RECHARGE, 9002);
        Path log = dir.resolve("robots").resolve("r1").resolve("monitor.log");
        Files.createDirectories(log.getParent());
        return Files.writeString(log, String.join("\n", recharge.lines().limit(2000).toList()) + "\n");
    }

    /** What the page shows of the scorecard and of the robot's forecast, once the robot's tile is OK. */
    private JsonNode page(ModelSet models, Abstraction abstraction, String screenshot) throws Exception {
        assumeTrue(browser != null, "no Chromium found (apt-get install chromium, or -Dpredmon.chromium=PATH): the "
                + "scorecard is not tested in a browser");
        Path log = robot();
        try (LiveScene scene = new LiveScene(models, abstraction, Duration.ofMinutes(10), RobotNames.pattern("{dir}"),
                List.of())) {
            scene.follow(log);
            HeadlessChromium.Page tab = browser.open(URI.create("about:blank"));
            try {
                tab.call("Emulation.setDeviceMetricsOverride", JSON.createObjectNode().put("width", 1920)
                        .put("height", 1080).put("deviceScaleFactor", 1).put("mobile", false));
                tab.call("Page.navigate", JSON.createObjectNode().put("url", scene.url().toString()));
                String tile = "document.querySelector('article.tile')";
                long deadline = System.nanoTime() + 30_000_000_000L;
                while (!"true".equals(tab.eval("String(!!(" + tile + " && " + tile + ".dataset.state === 'ok' && "
                        + tile + ".querySelector('.forecast')))"))) {
                    assertTrue(System.nanoTime() < deadline, "timed out waiting for the robot's OK tile");
                    Thread.sleep(50);
                }
                JsonNode shown = JSON.readTree(tab.eval("JSON.stringify({card: document.getElementById('scorecard')"
                        + ".innerText, cardHidden: document.getElementById('scorecard').hidden, forecast: " + tile
                        + ".querySelector('.forecast').innerText, headline: !!" + tile + ".querySelector("
                        + "'.forecast .chance')})"));
                tab.screenshot(Path.of("target", screenshot));
                String docs = System.getProperty("predmon.screenshots");
                if (docs != null && !docs.isBlank() && screenshot.equals("live-no-skill.png")) {
                    tab.screenshot(Path.of(docs, screenshot));
                }
                // the compact view: the row's words carry no probability either way it has no skill
                tab.call("Page.navigate", JSON.createObjectNode().put("url", scene.url() + "?view=compact"));
                deadline = System.nanoTime() + 30_000_000_000L;
                while (!"true".equals(tab.eval("String(!!document.querySelector('.row .line2'))"))) {
                    assertTrue(System.nanoTime() < deadline, "timed out waiting for the compact row");
                    Thread.sleep(50);
                }
                ((ObjectNode) shown).put("row",
                        tab.eval("document.querySelector('.row .line2').textContent"));
                return shown;
            } finally {
                tab.call("Page.close", JSON.createObjectNode());
            }
        }
    }

    @Test
    @Timeout(180)
    void theScorecardIsUnderTheHeaderAndAForecastWithSkillIsTheHeadline() throws Exception {
        ModelSet models = models();
        Scorecard c = models.forecast().scorecards().get(0);
        assertTrue(c.skill(), "the sample logs' models know more than the base rate: " + c);
        JsonNode shown = page(models, abstraction(), "live-skill.png");
        assertFalse(shown.get("cardHidden").asBoolean());
        assertTrue(shown.get("card").asText().startsWith("these models warned " + c.warned() + " of " + c.violating()
                + " violations in cross-validation"), shown.toString());
        assertFalse(shown.get("card").asText().contains("no skill"), shown.toString());
        assertTrue(shown.get("headline").asBoolean(), "the probability is the headline: " + shown);
        // below the threshold the headline is how far the run is from a warning, not a countdown
        assertTrue(shown.get("forecast").asText().startsWith("battery: P 0."), "whose forecast: " + shown);
        assertTrue(shown.get("forecast").asText().contains("warning at"), shown.toString());
        assertTrue(shown.get("row").asText().contains("warning at"), "the row gives the distance: " + shown);
    }

    @Test
    @Timeout(180)
    void whereTheForecastHasNoSkillThePageSaysSoAndShowsNoHeadlineProbability() throws Exception {
        ModelSet read = models();
        Scorecard c = read.forecast().scorecards().get(0);
        // the same models, scored as the 43 real recordings score theirs: no better than the base rate
        Scorecard noSkill = new Scorecard(c.property(), 5, 43, 11, 2, 1, 61, "ticks", 0.201, 0.196);
        ModelSet models = new ModelSet(read.dir(), read.index(), read.models(),
                read.forecast().withScorecards(List.of(noSkill)));
        JsonNode shown = page(models, abstraction(), "live-no-skill.png");
        assertTrue(shown.get("card").asText().contains("these models warned 2 of 11 violations in cross-validation, "
                + "1 false alarm(s) in 32 safe runs; Brier 0.201 vs base rate 0.196"), shown.toString());
        assertTrue(shown.get("card").asText().contains("the forecast has no skill on these models"),
                shown.toString());
        assertFalse(shown.get("headline").asBoolean(), "no probability as the headline: " + shown);
        assertTrue(shown.get("forecast").asText().startsWith("the forecast has no skill on these models"),
                shown.toString());
        assertEquals("OK", shown.get("row").asText(), "the row gives no chance: " + shown);
    }
}
