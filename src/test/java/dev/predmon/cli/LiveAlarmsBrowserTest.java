package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.forecast.Forecast;
import dev.predmon.live.RobotNames;
import dev.predmon.live.Tile;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import dev.predmon.support.LiveWatch;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The live page's alarms and names in a real browser (headless Chromium at 1920x1080): a warned run that recovered
 * shows "recovered" and no "Do now", a warning while the action is under way says so, models that do not fit show no
 * verdict and no forecast, a log not written yet says so, a file that is not a monitor log says so within 5 s, one
 * robot uses the screen, and fifty robots with long default names fit the compact view with their distinguishing
 * names readable. Skipped, with a message, without Chromium.
 *
 * <p>Screenshots go to {@code target/}, and with {@code -Dpredmon.screenshots=docs} to the documentation.
 */
class LiveAlarmsBrowserTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int WIDTH = BrowserTabs.WIDTH;
    private static final Set<String> DOCUMENTED = Set.of("live-alarms.png", "live-single.png", "live-names.png");
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();

    @TempDir
    Path dir;

    private static HeadlessChromium.Page open(URI url) throws Exception {
        return TABS.open(url, "the live page's alarms are not tested in a browser");
    }

    private static String of(String log) throws Exception {
        return "[...document.querySelectorAll('[data-log]')].find(a => a.dataset.log === "
                + JSON.writeValueAsString(log) + ")";
    }

    private static String text(HeadlessChromium.Page page, String element) throws Exception {
        return page.eval("(" + element + ").innerText");
    }

    private static Forecast forecast(double p, double level) {
        return new Forecast(p, 400.0, 300.0, 900.0, Forecast.Basis.MATCHED, null, 33, 7, level, -0.1, "s");
    }

    /** A run warned by the novelty clause at 29.64, the action under way, then recharged to 96.73: recovered. */
    private static void recovered(LiveScene scene, Tile t) {
        for (int tick = 1; tick <= 66; tick++) {
            scene.records(t, new Records().at(tick).level(60 - tick * 0.46).list());
        }
        scene.event(t, new MonitorEvent.Warning(66, 900, List.of(), 29.64, 12, Clock.SECONDS, 0,
                WarningRule.FORECAST, forecast(0.23, 29.64), "P(violation) 0.23 beyond what the training runs that held "
                + "did, with the value below the lowest they went to", MonitorEvent.Clause.NOVELTY));
        scene.event(t, new MonitorEvent.UnderWay(70, 950, "skill GoToChargingStation", true, Clock.SECONDS, 0));
        for (int tick = 67; tick <= 140; tick++) {
            scene.records(t, new Records().at(tick).level(Math.min(96.73, 29.64 + (tick - 66) * 1.2)).list());
        }
        scene.event(t, new MonitorEvent.Recovered(80, 1200, "action", 41.64, "recovered by the action, under way since "
                + "line 950: the value rose from 29.64 to 41.64", Clock.SECONDS, 0));
        scene.event(t, new MonitorEvent.ForecastChanged(140, 2000, forecast(0.21, 96.73), Clock.SECONDS, 0));
    }

    @Test
    @Timeout(120)
    void aRecoveredRunAnActionUnderWayModelsThatDoNotFitAndALogNotWrittenYet() throws Exception {
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofMinutes(10), RobotNames.pattern("{file}"),
                List.of())) {
            scene.board.warnsAt(WarningRule.FORECAST, scene.models);
            Tile r1 = scene.board.tile(dir.resolve("r1.log").toString());
            recovered(scene, r1);
            Tile r2 = scene.board.tile(dir.resolve("r2.log").toString());
            for (int tick = 1; tick <= 40; tick++) {
                scene.records(r2, new Records().at(tick).level(50 - tick * 0.5).list());
            }
            scene.event(r2, new MonitorEvent.UnderWay(36, 700, "goTo charging_station", true, Clock.SECONDS, 0));
            scene.event(r2, new MonitorEvent.Warning(40, 800, List.of("depleted"), 30.0, 12, Clock.SECONDS, 0,
                    WarningRule.FORECAST, forecast(0.91, 30.0), "P(violation) 0.91 reaches the warning threshold 0.86",
                    MonitorEvent.Clause.FORECAST));
            Tile r3 = scene.board.tile(dir.resolve("r3.log").toString());
            scene.records(r3, new Records().at(1).level(80).list());
            scene.event(r3, new MonitorEvent.ForecastChanged(1, 10, forecast(0.54, 80), Clock.SECONDS, 0));
            r3.noVerdict("the models' abstraction 'thesis' does not fit this log: most of its interface messages "
                    + "have no rule (ArmService/preGrasp, ...); learn with --abstraction scope-fetch");
            scene.board.tile(dir.resolve("r4.log").toString());

            HeadlessChromium.Page page = open(scene.url());
            page.await("document.querySelectorAll('article.tile').length === 4", "four tiles", 30);
            String t1 = of(dir.resolve("r1.log").toString());
            assertEquals("ok", page.eval(t1 + ".dataset.state"));
            String words1 = text(page, t1);
            assertTrue(words1.contains("RECOVERED"), words1);
            assertTrue(words1.contains("recovered t=80.00 s"), "the recovery, when: " + words1);
            assertTrue(words1.contains("warned t=66.00 s (29.64%)"), "the warning stays in this run: " + words1);
            assertFalse(words1.contains("Do now"), words1);
            assertTrue(words1.contains("P 0.21, warning at " + String.format(Locale.ROOT, "%.2f",
                    scene.models.forecast().threshold())), "how far from a warning: " + words1);
            assertFalse(words1.contains("chance of a violation"), "no countdown below the threshold: " + words1);

            String t2 = of(dir.resolve("r2.log").toString());
            assertEquals("warning", page.eval(t2 + ".dataset.state"));
            String words2 = text(page, t2);
            assertTrue(words2.contains("Under way since t=36.00 s"), words2);
            assertFalse(words2.contains("Do now"), words2);
            assertTrue(words2.contains("WARNING: the forecast predicts a violation"), "the clause: " + words2);

            String t3 = of(dir.resolve("r3.log").toString());
            assertEquals("no-verdict", page.eval(t3 + ".dataset.state"));
            String words3 = text(page, t3);
            assertTrue(words3.contains("NO VERDICT") && words3.contains("--abstraction scope-fetch"), words3);
            assertFalse(words3.contains("chance") || words3.contains("P 0.54"), "no forecast: " + words3);

            String words4 = text(page, of(dir.resolve("r4.log").toString()));
            assertTrue(words4.contains("no such file yet"), words4);
            assertFalse(words4.contains("log grew"), words4);
            BrowserTabs.screenshot(page, "live-alarms.png", DOCUMENTED);

            page.eval("document.getElementById('view').click(), 'ok'");
            page.await("document.querySelectorAll('#tiles.compact .row').length === 4", "the compact view", 30);
            String row1 = text(page, t1);
            assertTrue(row1.contains("OK, recovered t=80.00 s") && row1.contains("P 0.21, warning at"), row1);
            String row2 = text(page, t2);
            assertTrue(row2.contains("under way since t=36.00 s"), row2);
            assertFalse(row2.contains("send the robot"), "no action to do while it is under way: " + row2);
            BrowserTabs.screenshot(page, "live-alarms-compact.png", DOCUMENTED);
        }
    }

    @Test
    @Timeout(120)
    void aFileThatIsNotAMonitorLogSaysSoWithinFiveSeconds() throws Exception {
        Path robots = Files.createDirectories(dir.resolve("robots"));
        try (LiveWatch watch = LiveWatch.start("--log", robots.toString(), "--models", "models")) {
            HeadlessChromium.Page page = open(watch.url());
            page.await("!document.getElementById('empty').hidden", "the empty page", 30);
            StringBuilder info = new StringBuilder();
            for (int i = 0; i < 40; i++) {
                info.append("[INFO] |yarp.os.Port| Port /tool").append(i).append(" active at tcp://10.0.0.1:10002/\n");
            }
            Path notes = Files.writeString(robots.resolve("yarp.log"), info);
            long written = System.nanoTime();
            page.await(of(notes.toString()) + ".dataset.state === 'no-verdict'", "says no verdict", 10);
            double seconds = (System.nanoTime() - written) / 1e9;
            assertTrue(seconds < 5, "within 5 s: " + seconds);
            assertTrue(text(page, of(notes.toString())).contains("not a monitor log?"));
            assertTrue(watch.err().contains("not a monitor log?"), watch.err());
        }
    }

    @Test
    @Timeout(120)
    void oneRobotUsesTheScreen() throws Exception {
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofMinutes(10), RobotNames.byFile(),
                List.of())) {
            scene.board.warnsAt(WarningRule.FORECAST, scene.models);
            recovered(scene, scene.board.tile(dir.resolve("monitor2022-10-11T15_17+02_00.txt").toString()));
            HeadlessChromium.Page page = open(scene.url());
            page.await("document.querySelector('article.tile svg.plot') !== null", "the tile", 30);
            JsonNode size = JSON.readTree(page.eval("JSON.stringify({tile: document.querySelector('article.tile')"
                    + ".getBoundingClientRect().width, plot: document.querySelector('article.tile svg.plot')"
                    + ".getBoundingClientRect().width, name: document.querySelector('article.tile h2').textContent})"));
            assertTrue(size.get("tile").asDouble() > WIDTH * 0.9, "the tile spans the screen: " + size);
            assertTrue(size.get("plot").asDouble() > WIDTH * 0.5, "a large plot: " + size);
            assertEquals("monitor2022-10-11T15_17+02_00", size.get("name").asText(), "one log: its whole name");
            BrowserTabs.screenshot(page, "live-single.png", DOCUMENTED);
        }
    }

    @Test
    @Timeout(120)
    void fiftyRobotsWithLongDefaultNamesFitTheCompactViewWithTheirNamesReadable() throws Exception {
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofMinutes(10), RobotNames.byFile(),
                List.of())) {
            scene.board.warnsAt(WarningRule.FORECAST, scene.models);
            List<String> expected = new ArrayList<>();
            for (int i = 0; i < 50; i++) {
                String time = String.format(Locale.ROOT, "%02d_%02d", 9 + i / 6, (i % 6) * 10);
                expected.add(time);
                Tile t = scene.board.tile(dir.resolve("monitor2022-10-11T" + time + "+02_00.txt").toString());
                scene.records(t, new Records().at(1).level(40 + i).list());
                scene.event(t, new MonitorEvent.ForecastChanged(1, 10, forecast(0.05 + i / 100.0, 40 + i),
                        Clock.SECONDS, 0));
                if (i % 7 == 0) {
                    scene.event(t, new MonitorEvent.Warning(1, 20, List.of(), 40.0 + i, 2, Clock.SECONDS, 0,
                            WarningRule.FORECAST, forecast(0.9, 40 + i), "P(violation) 0.90 reaches the warning "
                            + "threshold 0.86", MonitorEvent.Clause.FORECAST));
                }
            }
            HeadlessChromium.Page page = open(scene.url().resolve("/?view=compact"));
            page.await("document.querySelectorAll('#tiles.compact .row').length === 50", "50 rows", 30);
            JsonNode fit = JSON.readTree(page.eval("JSON.stringify({outside: [...document.querySelectorAll('.row')]"
                    + ".filter(r => { const b = r.getBoundingClientRect(); return b.top < 0 || b.left < 0"
                    + " || b.bottom > innerHeight || b.right > innerWidth; }).length,"
                    + " cut: [...document.querySelectorAll('.row .name')].filter(n => n.scrollWidth > n.clientWidth)"
                    + ".map(n => n.textContent), names: [...document.querySelectorAll('.row .name')]"
                    + ".map(n => n.textContent).sort()})"));
            assertEquals(0, fit.get("outside").asInt(), "every row on the screen");
            assertEquals(0, fit.get("cut").size(), "no name cut: " + fit.get("cut"));
            List<String> names = new ArrayList<>();
            fit.get("names").forEach(n -> names.add(n.asText()));
            assertEquals(expected.stream().sorted().toList(), names, "the part all logs share dropped");
            BrowserTabs.screenshot(page, "live-names.png", DOCUMENTED);
        }
    }
}
