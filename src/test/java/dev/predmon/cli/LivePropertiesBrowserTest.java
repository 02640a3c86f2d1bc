package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.live.RobotNames;
import dev.predmon.live.Tile;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * One light per property on each robot's tile, worst first, in a real browser (headless Chromium at 1920x1080), with
 * the shipped models and their five properties, each robot's records going through its own monitor as in watch: a
 * navigation that aborts (no-abort red), one stuck past every training navigation (navigation-in-time yellow, its
 * warning's words), one warned that then arrives (green again, with its recovery), and one under way (green, pending,
 * with its chance of a miss). In the compact view each row shows its worst property's light and id. Skipped, with a
 * message, on a machine without Chromium.
 *
 * <p>{@code docs/live-properties.png} is made with
 * {@code mvn -q test -Dtest=LivePropertiesBrowserTest -Dpredmon.screenshots=docs}.
 */
class LivePropertiesBrowserTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    /** The screenshot the documentation shows. */
    private static final Set<String> DOCUMENTED = Set.of("live-properties.png");
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();

    @TempDir
    Path dir;

    /** A robot's log as records: a tick a second, with a battery reading at each, and what else {@code at} adds. */
    private static final class Robot {
        private final List<LogRecord> records = new ArrayList<>();
        private long line = 1;

        Robot tick(int n, double level) {
            add(RecordKind.TICK, "/tick/monitor", "/monitor", "Tick", "", Integer.toString(n), "", n);
            add(RecordKind.COMMAND, "/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader", "level",
                    "", "", n + 0.1);
            add(RecordKind.REPLY, "/BatteryComponent", "/BatteryReaderBatteryLevelClient", "BatteryReader", "level",
                    "", String.format(Locale.ROOT, "%.6f", level), n + 0.2);
            return this;
        }

        Robot goTo(int n, String where) {
            add(RecordKind.COMMAND, "/GoToGoToClient/" + where, "/GoToComponent", "GoTo", "goTo", where, "", n + 0.3);
            add(RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/" + where, "GoTo", "goTo", where, "", n + 0.4);
            return this;
        }

        Robot status(int n, String where, int status) {
            add(RecordKind.COMMAND, "/GoToGoToClient/" + where, "/GoToComponent", "GoTo", "getStatus", where, "",
                    n + 0.5);
            add(RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/" + where, "GoTo", "getStatus", where,
                    Integer.toString(status), n + 0.6);
            return this;
        }

        /** Ticks {@code from} to {@code to}, the battery slowly falling from 90. */
        Robot ticks(int from, int to) {
            for (int n = from; n <= to; n++) {
                tick(n, 90 - n * 0.01);
            }
            return this;
        }

        private void add(RecordKind kind, String from, String to, String protocol, String command, String arg,
                         String reply, double time) {
            records.add(new LogRecord(line, time, "DEBUG", kind, from, to, protocol, command, arg, reply));
            line += 7;
        }
    }

    private static String of(String log) throws Exception {
        return "[...document.querySelectorAll('[data-log]')].find(a => a.dataset.log === "
                + JSON.writeValueAsString(log) + ")";
    }

    /** Each light of a robot's tile, in the page's order: {@code property state}. */
    private static List<String> lights(HeadlessChromium.Page page, String log) throws Exception {
        JsonNode a = JSON.readTree(page.eval("JSON.stringify([...(" + of(log) + ").querySelectorAll('li.prop')]"
                + ".map(l => l.dataset.property + ' ' + l.dataset.state))"));
        List<String> out = new ArrayList<>();
        a.forEach(x -> out.add(x.asText()));
        return out;
    }

    @Test
    @Timeout(180)
    void eachTileShowsOneLightPerPropertyWorstFirst() throws Exception {
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofMinutes(10), RobotNames.pattern("{file}"),
                List.of())) {
            String aborts = dir.resolve("r1.log").toString();
            String stuck = dir.resolve("r2.log").toString();
            String arrived = dir.resolve("r3.log").toString();
            String underWay = dir.resolve("r4.log").toString();
            // the training navigations took at most 285 ticks: past them, one is warned half way to the 400-tick
            // deadline, at (285 + 400) / 2 = 342.5 ticks pending
            scene.feed(scene.board.tile(aborts), new Robot().ticks(1, 3).goTo(3, "kitchen").ticks(4, 5)
                    .status(5, "kitchen", 3).ticks(6, 8).records);
            scene.feed(scene.board.tile(stuck), new Robot().ticks(1, 1).goTo(1, "kitchen").ticks(2, 350).records);
            scene.feed(scene.board.tile(arrived), new Robot().ticks(1, 1).goTo(1, "kitchen").ticks(2, 350)
                    .status(350, "kitchen", 2).ticks(351, 355).records);
            Tile r4 = scene.board.tile(underWay);
            scene.feed(r4, new Robot().ticks(1, 1).goTo(1, "kitchen").ticks(2, 40).records);

            HeadlessChromium.Page page = TABS.open(scene.url(), "the live page is not tested in a browser");
            page.await("document.querySelectorAll('article.tile li.prop').length === 20", "five lights on four tiles",
                    30);

            List<String> r1 = lights(page, aborts);
            assertEquals("no-abort violated", r1.get(0), "worst first: " + r1);
            assertEquals(5, r1.size(), r1.toString());
            assertTrue(page.eval("(" + of(aborts) + ").querySelector('li.prop').textContent")
                    .contains("violated at line"), "the violation's line and event");

            List<String> r2 = lights(page, stuck);
            assertEquals("navigation-in-time warning", r2.get(0), r2.toString());
            String warned = page.eval("(" + of(stuck) + ").querySelector('li.prop').textContent");
            assertTrue(warned.contains("longer than any of the") && warned.contains("ticks left"), warned);
            assertTrue(warned.contains("check whether the robot is stuck"), "its action: " + warned);

            List<String> r3 = lights(page, arrived);
            assertTrue(r3.contains("navigation-in-time holds"), r3.toString());
            String recovered = page.eval("[...(" + of(arrived) + ").querySelectorAll('li.prop')].find(l => "
                    + "l.dataset.property === 'navigation-in-time').textContent");
            assertTrue(recovered.contains("recovered") && recovered.contains("the response came in time"), recovered);
            String events = page.eval("(" + of(arrived) + ").querySelector('section.events').textContent");
            assertTrue(events.contains("RECOVERED (navigation-in-time)"), events);

            List<String> r4lights = lights(page, underWay);
            // properties nothing of which occurred yet are grey (no evidence), above the greens; then the pending
            List<String> known = r4lights.stream().filter(l -> !l.endsWith("no-evidence")).toList();
            assertEquals("navigation-in-time pending", known.get(0), r4lights.toString());
            assertTrue(r4lights.indexOf(known.get(0)) == r4lights.size() - known.size(), r4lights.toString());
            String nav = "[...(" + of(underWay) + ").querySelectorAll('li.prop')].find(l => "
                    + "l.dataset.property === 'navigation-in-time')";
            String pending = page.eval(nav + ".textContent");
            assertTrue(pending.contains("P(miss)") && pending.contains("ticks left")
                    && pending.contains("skill not measured"), pending);
            assertEquals("green", page.eval(nav + ".querySelector('.light').className.split(' ').pop()"));

            JsonNode order = JSON.readTree(page.eval("JSON.stringify([...document.querySelectorAll('article.tile')]"
                    + ".map(t => t.dataset.log))"));
            assertEquals(aborts, order.get(0).asText(), "the robot with a property violated first: " + order);
            assertEquals(stuck, order.get(1).asText(), "then the one warned: " + order);
            // the robot's own light, beside its name, is its worst property's, though its battery holds
            String own = "(l => l.className.split(' ').pop() + ' ' + l.getAttribute('aria-label'))";
            assertEquals("red VIOLATION", page.eval(own + "((" + of(aborts) + ").querySelector('.light'))"));
            assertEquals("yellow WARNING", page.eval(own + "((" + of(stuck) + ").querySelector('.light'))"));
            BrowserTabs.screenshot(page, "live-properties.png", DOCUMENTED);

            page.eval("document.getElementById('view').click(), 'ok'");
            page.await("document.querySelectorAll('#tiles.compact .row .worst').length === 4", "the compact view",
                    30);
            JsonNode rows = JSON.readTree(page.eval("JSON.stringify([...document.querySelectorAll('.row')].map(r => "
                    + "({log: r.dataset.log, light: r.dataset.light, worst: (r.querySelector('.worst .worst-text') || {}).textContent || '', state: r.querySelector('.worst').dataset.state})))"));
            assertEquals("red", rows.get(0).get("light").asText(), rows.toString());
            assertEquals("no-abort", rows.get(0).get("worst").asText(), rows.toString());
            assertEquals("violated", rows.get(0).get("state").asText(), rows.toString());
            assertEquals("navigation-in-time", rows.get(1).get("worst").asText(), rows.toString());
            assertEquals("warning", rows.get(1).get("state").asText(), rows.toString());
            assertEquals("", rows.get(2).get("worst").asText(), "the others well: their light alone " + rows);
            // its worst is a property nothing of which occurred yet: no evidence, never "holds"
            assertEquals("no-evidence", rows.get(2).get("state").asText(), rows.toString());
            assertEquals("yellow", rows.get(1).get("light").asText(), rows.toString());
            BrowserTabs.screenshot(page, "live-properties-compact.png", DOCUMENTED);
        }
    }
}
