package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.simulate.Day;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import dev.predmon.support.LiveWatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The live page in a real browser (headless Chromium): {@code watch --http} follows a log that a simulated faulty run
 * is appended to, and the page, left open, turns the tile yellow at the warning, then red at the violation, and then
 * shows the lead. Skipped, with a message, on a machine without Chromium.
 *
 * <p>It also saves a screenshot to {@code target/live-browser.png}, and to {@code -Dpredmon.screenshot=FILE} when
 * given: the README's {@code docs/live.png} is made with
 * {@code mvn -q test -Dtest=LiveBrowserTest -Dpredmon.screenshot=docs/live.png}.
 */
class LiveBrowserTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final SimOptions O = SimOptions.defaults();
    private static final Path MODELS = Path.of("models");
    /** The README's screenshot's size. */
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs(1400, 940);

    @TempDir
    Path dir;

    /** A log's text cut before the records at the warning's and the violation's lines: three parts. */
    private static String[] cut(String text, long warningLine, long violationLine) {
        List<String> lines = text.lines().toList();
        StringBuilder[] parts = {new StringBuilder(), new StringBuilder(), new StringBuilder()};
        for (int i = 0; i < lines.size(); i++) {
            int part = i + 1 < warningLine ? 0 : i + 1 < violationLine ? 1 : 2;
            parts[part].append(lines.get(i)).append('\n');
        }
        return new String[] {parts[0].toString(), parts[1].toString(), parts[2].toString()};
    }

    /** The events {@code watch --json --no-follow} gives for a log. */
    private static List<JsonNode> events(Path log) throws Exception {
        return Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow", "--json")
                .jsonLines();
    }

    private static JsonNode first(List<JsonNode> events, String kind) {
        return Cli.firstEvent(events, kind).orElseThrow();
    }

    /** The tile of {@code log} as the page shows it: light, run, lead text, verdict; "none" before it exists. */
    private static String tileState(HeadlessChromium.Page page, String log) throws Exception {
        return page.eval("(() => { const t = [...document.querySelectorAll('article.tile')].find(a => a.dataset.log === "
                + JSON.writeValueAsString(log) + "); if (!t) return 'none';"
                + " const lead = t.querySelector('.lead:not(.none)');"
                + " const runs = t.querySelector('.runs');"
                + " return JSON.stringify({light: t.dataset.light, run: t.dataset.run,"
                + " lead: lead ? lead.textContent : null, verdict: t.querySelector('.verdict').textContent,"
                + " earlier: runs ? runs.textContent : ''});"
                + " })()");
    }

    /** Polls the page until the tile's light is {@code light}, noting every light seen on the way. */
    private static JsonNode until(HeadlessChromium.Page page, String log, String light, List<String> seen)
            throws Exception {
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (System.nanoTime() < deadline) {
            String s = tileState(page, log);
            if (!"none".equals(s)) {
                JsonNode state = JSON.readTree(s);
                String now = state.get("light").asText();
                if (seen.isEmpty() || !seen.get(seen.size() - 1).equals(now)) {
                    seen.add(now);
                }
                if (now.equals(light)) {
                    return state;
                }
            }
            Thread.sleep(40);
        }
        throw new AssertionError("the tile of " + log + " never turned " + light + "; lights seen: " + seen);
    }

    @Test
    @Timeout(180)
    void theTileTurnsYellowBeforeRedAndShowsTheLead() throws Exception {
        TABS.assumeBrowser("the live page is not tested in a browser");

        // robot-1: a robot's day, a direct run then a depleted one, the depleted one appended while the page is open.
        StringBuilder day = new StringBuilder();
        for (SimRun run : Day.simulate(List.of(Scenario.DIRECT, Scenario.DEPLETED), 11, 2, O)) {
            day.append(LogWriter.toText(run, O));
        }
        Path full = Files.writeString(dir.resolve("full.log"), day);
        List<JsonNode> truth = events(full);
        JsonNode warning = first(truth, "warning");
        JsonNode violation = first(truth, "violation");
        assertEquals(1, warning.get("run").asInt(), "the depleted run is the day's second");
        String[] parts = cut(day.toString(), warning.get("line").asLong(), violation.get("line").asLong());

        Path robots = Files.createDirectories(dir.resolve("robots"));
        Path robot1 = robots.resolve("robot-1.log");
        Files.writeString(robot1, parts[0]);
        // robot-2: a nominal run, complete (green); robot-3: a depleted run cut after its warning (yellow).
        Files.writeString(robots.resolve("robot-2.log"), FleetWatchTest.run(Scenario.RECHARGE, 9002));
        String other = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        Path otherFull = Files.writeString(dir.resolve("other.log"), other);
        List<JsonNode> otherTruth = events(otherFull);
        Files.writeString(robots.resolve("robot-3.log"), cut(other, first(otherTruth, "warning").get("line").asLong(),
                first(otherTruth, "violation").get("line").asLong())[0]
                + cut(other, first(otherTruth, "warning").get("line").asLong(),
                first(otherTruth, "violation").get("line").asLong())[1]);

        try (LiveWatch watch = LiveWatch.start("--log", robots.toString(), "--models", MODELS.toString(),
                "--stale-after", "60")) {
            HeadlessChromium.Page page = watch.open(TABS, "the live page is not tested in a browser");
            List<String> seen = new ArrayList<>();

            JsonNode green = until(page, robot1.toString(), "green", seen);
            assertEquals("1", green.get("run").asText(), "the second run of the log: " + green);
            assertNull(green.get("lead").textValue(), "no lead yet");
            assertTrue(green.get("earlier").asText().contains("run 0"), "run 0's verdict stays visible: " + green);
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (!"live".equals(page.eval("document.getElementById('connection').dataset.state"))) {
                assertTrue(System.nanoTime() < deadline, "the page's event stream never connected");
                Thread.sleep(40);
            }

            Files.writeString(robot1, parts[1], StandardOpenOption.APPEND); // up to just before the violation
            JsonNode yellow = until(page, robot1.toString(), "yellow", seen);
            assertTrue(yellow.get("verdict").asText().contains("WARNING"), yellow.toString());
            assertNull(yellow.get("lead").textValue(), "the lead needs the violation too: " + yellow);

            Files.writeString(robot1, parts[2], StandardOpenOption.APPEND);
            JsonNode red = until(page, robot1.toString(), "red", seen);
            String lead = String.format(Locale.ROOT, "lead %.2f s", violation.get("time").asDouble()
                    - warning.get("time").asDouble());
            assertTrue(red.get("lead").asText().startsWith(lead), "shows the lead (" + lead + "): " + red);
            assertEquals(List.of("green", "yellow", "red"), seen, "yellow before red, without reloading the page");

            assertEquals("green", JSON.readTree(tileState(page, robots.resolve("robot-2.log").toString()))
                    .get("light").asText());
            assertEquals("yellow", JSON.readTree(tileState(page, robots.resolve("robot-3.log").toString()))
                    .get("light").asText());
            page.screenshot(Path.of("target", "live-browser.png"));
            String docs = System.getProperty("predmon.screenshot");
            if (docs != null && !docs.isBlank()) {
                page.screenshot(Path.of(docs));
            }
        }
    }
}
