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
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
    /** The screenshot the documentation shows. */
    private static final Set<String> DOCUMENTED = Set.of("live-no-skill.png");
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();

    @TempDir
    Path dir;

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
        TABS.assumeBrowser("the scorecard is not tested in a browser");
        Path log = robot();
        try (LiveScene scene = new LiveScene(models, abstraction, Duration.ofMinutes(10), RobotNames.pattern("{dir}"),
                List.of())) {
            scene.follow(log);
            HeadlessChromium.Page tab = TABS.open(scene.url(), "the scorecard is not tested in a browser");
            String tile = "document.querySelector('article.tile')";
            tab.await(tile + " && " + tile + ".dataset.state === 'ok' && " + tile + ".querySelector('.forecast')",
                    "the robot's OK tile", 30);
            JsonNode shown = JSON.readTree(tab.eval("JSON.stringify({card: document.getElementById('scorecard')"
                    + ".innerText, cardHidden: document.getElementById('scorecard').hidden, forecast: " + tile
                    + ".querySelector('.forecast').innerText, headline: !!" + tile + ".querySelector("
                    + "'.forecast .chance')})"));
            BrowserTabs.screenshot(tab, screenshot, DOCUMENTED);
            // the compact view: the row's words carry no probability either way it has no skill
            tab.call("Page.navigate", JSON.createObjectNode().put("url", scene.url() + "?view=compact"));
            tab.await("document.querySelector('.row .line2')", "the compact row", 30);
            ((ObjectNode) shown).put("row", tab.eval("document.querySelector('.row .line2').textContent"));
            return shown;
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
