package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.forecast.Forecast;
import dev.predmon.live.RobotNames;
import dev.predmon.live.Tile;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.simulate.Scenario;
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
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The live page as an operator beside the robots uses it, in a real browser (headless Chromium at 1920x1080): the
 * UNKNOWN tile of a run no model matches, acknowledging a tile until its state changes (with the opt-in notification),
 * a hundred robots on one screen in the compact view, and the empty page saying what it waits for. Skipped, with a
 * message, on a machine without Chromium.
 *
 * <p>Screenshots go to {@code target/}, and to {@code -Dpredmon.screenshots=DIR} when given: the documentation's
 * {@code docs/live-fleet.png} and {@code docs/live-compact.png} are made with
 * {@code mvn -q test -Dtest=LivePageBrowserTest -Dpredmon.screenshots=docs}.
 */
class LivePageBrowserTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int WIDTH = BrowserTabs.WIDTH;
    private static final int HEIGHT = BrowserTabs.HEIGHT;
    /** The screenshots the documentation shows. */
    private static final Set<String> DOCUMENTED = Set.of("live-fleet.png", "live-compact.png");
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();

    @TempDir
    Path dir;

    private HeadlessChromium.Page open(URI url) throws Exception {
        HeadlessChromium.Page page = TABS.blank("the live page is not tested in a browser");
        // Stand-ins for the browser's notifications and sound, which a headless browser cannot show or play.
        page.call("Page.enable", JSON.createObjectNode());
        page.call("Page.addScriptToEvaluateOnNewDocument", JSON.createObjectNode().put("source", """
                window.__notes = []; window.__beeps = 0; window.__errors = [];
                addEventListener('error', (e) => window.__errors.push(e.message));
                addEventListener('unhandledrejection', (e) => window.__errors.push(String(e.reason)));
                window.Notification = class { constructor(title) { window.__notes.push(title); }
                  static get permission() { return 'granted'; }
                  static requestPermission() { return Promise.resolve('granted'); } };
                window.AudioContext = class { constructor() { this.state = 'running'; this.currentTime = 0;
                  this.destination = {}; }
                  createOscillator() { window.__beeps++; return {frequency: {}, connect: (g) => g, start() {}, stop() {}}; }
                  createGain() { return {gain: {setValueAtTime() {}, exponentialRampToValueAtTime() {}},
                    connect: (d) => d}; }
                  resume() {} };"""));
        page.call("Page.navigate", JSON.createObjectNode().put("url", url.toString()));
        return page;
    }

    /** The element of a log (its tile or row), in JavaScript. */
    private static String of(String log) throws Exception {
        return "[...document.querySelectorAll('[data-log]')].find(a => a.dataset.log === "
                + JSON.writeValueAsString(log) + ")";
    }

    /**
     * Clicks {@code element} until {@code condition} holds: on a loaded machine the page can lay itself out again
     * between finding the element and the click, which then lands beside it.
     */
    private static void clickUntil(HeadlessChromium.Page page, String element, String condition, String what)
            throws Exception {
        for (int attempt = 1; ; attempt++) {
            click(page, element);
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (System.nanoTime() < deadline) {
                if ("true".equals(page.eval("String(!!(() => { try { return " + condition + "; } catch (e) { return "
                        + "false; } })())"))) {
                    return;
                }
                Thread.sleep(50);
            }
            assertTrue(attempt < 6, "timed out: " + what);
        }
    }

    /** A real click (mouse pressed and released) in the middle of the element {@code element} gives. */
    private static void click(HeadlessChromium.Page page, String element) throws Exception {
        JsonNode r = JSON.readTree(page.eval("JSON.stringify((" + element + ").getBoundingClientRect())"));
        double x = r.get("x").asDouble() + r.get("width").asDouble() / 2;
        double y = r.get("y").asDouble() + r.get("height").asDouble() / 2;
        for (String type : new String[] {"mousePressed", "mouseReleased"}) {
            page.call("Input.dispatchMouseEvent", JSON.createObjectNode().put("type", type).put("x", x).put("y", y)
                    .put("button", "left").put("clickCount", 1));
        }
    }

    /** The first warning's and violation's lines of a log, as {@code watch --json} finds them. */
    private static long[] lines(Path log, Path models) throws Exception {
        Cli w = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json");
        long warning = 0;
        long violation = 0;
        for (String line : w.out().split("\n", 0)) {
            JsonNode e = JSON.readTree(line);
            String kind = e.get("event").asText();
            if (kind.equals("warning") && warning == 0) {
                warning = e.get("line").asLong();
            } else if (kind.equals("violation") && violation == 0) {
                violation = e.get("line").asLong();
            }
        }
        return new long[] {warning, violation};
    }

    /** The log's first lines, up to (not with) line {@code before}. */
    private static String head(String text, long before) {
        return String.join("\n", text.lines().limit(before - 1).toList()) + "\n";
    }

    private static String tail(String text, long from) {
        return String.join("\n", text.lines().skip(from - 1).toList()) + "\n";
    }

    private Path robot(String name, String text) throws Exception {
        Path log = dir.resolve("robots").resolve(name).resolve("monitor.log");
        Files.createDirectories(log.getParent());
        return Files.writeString(log, text);
    }

    @Test
    @Timeout(180)
    void aRunNoModelMatchesIsUnknownNeitherGreenNorRedAndAnEmptyPageSaysWhatItWaitsFor() throws Exception {
        Path models = ForecastModels.get();
        Path robots = Files.createDirectories(dir.resolve("robots"));
        try (LiveWatch watch = LiveWatch.start("--log", robots.toString(), "--models", models.toString(),
                "--stale-after", "600", "--name-pattern", "{file}")) {
            HeadlessChromium.Page page = open(watch.url());
            page.await("!document.getElementById('empty').hidden", "the empty page", 30);
            String empty = page.eval("document.getElementById('empty').innerText");
            assertTrue(empty.contains("Waiting for logs") && empty.contains("logs in " + robots), empty);

            Cli sim = Cli.run("simulate", "--scenario", "direct", "--seed", "5", "--aborts", "2", "--out",
                    robots.resolve("blocked.log").toString());
            assertEquals(0, sim.code(), sim.err());
            String log = robots.resolve("blocked.log").toString();
            // the run's two aborts violate no-abort: the robot's state is that violation; its battery's, no model
            // matching the run, is unknown
            page.await(of(log) + ".querySelector('li.prop[data-property=battery]').dataset.state === 'unknown'",
                    "the blocked robot's battery turns unknown", 30);
            assertTrue(page.eval("document.getElementById('empty').hidden ? 'yes' : 'no'").equals("yes"));
            JsonNode tile = JSON.readTree(page.eval("JSON.stringify((() => { const t = " + of(log) + ";"
                    + " const light = t.querySelector('header .light');"
                    + " return {light: t.dataset.light, glyph: light.textContent, colour: getComputedStyle(light)"
                    + ".backgroundColor, verdict: t.querySelector('.verdict').textContent, name: t.querySelector('h2')"
                    + ".textContent, forecast: (t.querySelector('.forecast') || {}).textContent || ''}; })())"));
            // the tile, the robot's own light and its sentence are the worst property's: no-abort, violated
            assertEquals("red", tile.get("light").asText());
            assertEquals("\u2715", tile.get("glyph").asText());
            String colour = tile.get("colour").asText();
            assertFalse(colour.equals("rgb(30, 158, 74)"), "never green: " + colour);
            assertTrue(tile.get("verdict").asText().startsWith("VIOLATED: no-abort \u2014 line "), tile.toString());
            assertEquals("blocked", tile.get("name").asText(), "the robot's name, not the path");
            assertTrue(tile.get("forecast").asText().contains("warning at"), "how far from a warning: " + tile);
            BrowserTabs.screenshot(page, "live-unknown.png", DOCUMENTED);
        }
    }

    @Test
    @Timeout(180)
    void acknowledgeSilencesATileUntilItsStateChangesNext() throws Exception {
        Path models = ForecastModels.get();
        String depleted = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        Path full = Files.writeString(dir.resolve("full.log"), depleted);
        long[] at = lines(full, models);
        assertTrue(at[0] > 0 && at[1] > at[0], "a warning before the violation: " + at[0] + ", " + at[1]);
        Path warned = robot("r1", head(depleted, at[1]));
        String recharge = FleetWatchTest.run(Scenario.RECHARGE, 9002);
        Path fine = robot("r2", head(recharge, 2000));
        try (LiveScene scene = new LiveScene(models, Duration.ofMinutes(10), RobotNames.pattern("{dir}"), List.of())) {
            scene.follow(warned);
            scene.follow(fine);
            HeadlessChromium.Page page = open(scene.url());
            String r1 = of(warned.toString());
            page.await(r1 + ".dataset.state === 'warning'", "r1 warned", 30);
            assertEquals(warned.toString(), page.eval("document.querySelector('[data-log]').dataset.log"),
                    "the warning comes first");
            assertTrue(page.eval(r1 + ".querySelector('.action').textContent")
                    .contains("send the robot to the charging station"));
            assertEquals("sound off", page.eval("document.getElementById('sound').textContent"), "no sound by default");
            clickUntil(page, "document.getElementById('notify')",
                    "document.getElementById('notify').getAttribute('aria-pressed') === 'true'", "notifications on");

            clickUntil(page, r1 + ".querySelector('button.ack')", r1 + ".dataset.ack === 'true'", "acknowledged");
            assertEquals("acknowledged", page.eval(r1 + ".querySelector('button.ack').textContent"));
            assertTrue(page.eval("document.getElementById('summary').textContent").contains("1 acknowledged"));
            page.call("Page.reload", JSON.createObjectNode());
            page.await(of(warned.toString()) + ".dataset.ack === 'true'", "still acknowledged after a reload", 30);

            Files.writeString(warned, tail(depleted, at[1]), StandardOpenOption.APPEND);
            scene.follow(warned);
            page.await(r1 + ".dataset.state === 'violation'", "r1 violated", 30);
            // the watched value, as /status gives it, wherever the tile shows one
            JsonNode shown = JSON.readTree(page.eval("JSON.stringify((() => { const t = " + r1 + ";"
                    + " const text = s => (t.querySelector(s) || {}).textContent || '';"
                    + " return {now: text('.value-now'), verdict: text('.verdict'), lead: text('.lead'),"
                    + " history: text('.history'),"
                    + " warning: [...t.querySelectorAll('.events li.warning')].map(l => l.textContent)"
                    + ".find(l => l.includes('WARNING at ')) || '',"
                    + " violation: [...t.querySelectorAll('.events li.violation')].map(l => l.textContent)"
                    + ".find(l => l.includes('VIOLATION of battery')) || '',"
                    + " series: t.querySelectorAll('svg.plot polyline.series').length}; })())"));
            String percent = "\\d+\\.\\d\\d%";
            // the big number is the battery's, named: one property among the others
            assertTrue(shown.get("now").asText().matches("battery" + percent), shown.toString());
            assertTrue(shown.get("verdict").asText().matches("VIOLATED since t=.* \\(" + percent + "\\), predicted .*"),
                    shown.toString());
            assertTrue(shown.get("lead").asText().matches("lead .*: warning at " + percent + ", violation at "
                    + percent), shown.toString());
            assertTrue(shown.get("history").asText().matches("this run: warned t=.* \\(" + percent + "\\) \u2192 "
                    + "violated t=.* \\(" + percent + "\\).*"), shown.toString());
            // the battery's warning among the others (the depleted run is warned of its abort too)
            assertTrue(shown.get("warning").asText().matches(".*WARNING at " + percent + ": .*"), shown.toString());
            assertTrue(shown.get("violation").asText().matches(".*VIOLATION of battery: " + percent), shown.toString());
            assertEquals(1, shown.get("series").asInt(), "the value over the run: " + shown);
            page.await(r1 + ".dataset.ack === 'false'", "a new state lifts the acknowledgement", 30);
            assertEquals("acknowledge", page.eval(r1 + ".querySelector('button.ack').textContent"));
            page.await("window.__notes.length > 0", "a notification of the violation", 30);
            assertEquals("[\"r1: VIOLATION\"]", page.eval("JSON.stringify(window.__notes)"));
            assertEquals("0", page.eval("String(window.__beeps)"), "no sound unless switched on");
            click(page, "document.getElementById('sound')");
            page.await("window.__beeps > 0", "switching the sound on plays it once: " + page.eval(
                    "document.getElementById('sound').textContent + ' ' + JSON.stringify(window.__errors)"), 30);
            BrowserTabs.screenshot(page, "live-acknowledged.png", DOCUMENTED);
        }
    }

    /** What robot {@code i} of the hundred shows: a few of each state, the rest ok, all with a forecast. */
    private static void hundredth(LiveScene scene, Tile t, int i) {
        double level = 25 + (i * 37) % 70;
        List<LogRecord> records = new ArrayList<>(new Records().call("/GoToDestination/BT_rpc/client",
                "/GoToDestination/BT_rpc/server", "Skill_request", "send_start", "", "").at(i).level(level).list());
        if (i % 11 == 0) { // done: the tree stopped its skill
            records.addAll(new Records().at(i + 1).call("/GoToDestination/BT_rpc/client",
                    "/GoToDestination/BT_rpc/server", "Skill_request", "send_stop", "", "").list());
        }
        scene.records(t, records);
        double p = 0.05 + (i % 30) / 100.0;
        Forecast f = new Forecast(p, 40.0 + i, 30.0 + i, 60.0 + i, Forecast.Basis.MATCHED, null, 20, 4, level, -0.9, "s");
        if (i % 25 == 0) {
            scene.event(t, new MonitorEvent.Violation(i, 900, "battery level >= 20%", 19.95, 20.3, Clock.SECONDS, 0));
            scene.records(t, List.of(new Records().at(i + 2).level(19.95).list().get(1)));
        } else if (i % 9 == 0) {
            f = new Forecast(0.97, 6.5, 5.9, 7.4, Forecast.Basis.MATCHED, null, 10, 10, 31.2, -2.4, "s");
            scene.event(t, new MonitorEvent.Warning(i, 700, List.of(), 31.2, 12, Clock.SECONDS, 0, WarningRule.FORECAST,
                    f, "P(violation) 0.97 reaches the warning threshold 0.92"));
        } else if (i % 13 == 0) {
            scene.event(t, new MonitorEvent.NoMatch(i, 500, Clock.SECONDS, 0));
            f = new Forecast(0.4, 80.0, 60.0, null, Forecast.Basis.VALUE_ONLY, 500L, 20, 8, level, -0.5, "s");
        }
        scene.event(t, new MonitorEvent.ForecastChanged(i, 800, f, Clock.SECONDS, 0));
    }

    @Test
    @Timeout(180)
    void aHundredRobotsFitOneScreenInTheCompactView() throws Exception {
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofSeconds(2), RobotNames.byFile(),
                List.of())) {
            List<Tile> live = new ArrayList<>();
            for (int i = 1; i <= 100; i++) {
                Tile t = scene.board.tile(dir.resolve(String.format(Locale.ROOT, "robot-%03d.log", i)).toString());
                hundredth(scene, t, i);
                if (i % 11 != 0 && i % 19 != 0) { // these stop growing: ended, or stale mid-run
                    live.add(t);
                }
            }
            try (AutoCloseable growing = scene.growing(live)) {
                HeadlessChromium.Page page = open(scene.url().resolve("/?view=compact"));
                page.await("document.querySelectorAll('#tiles.compact .row').length === 100", "100 rows", 30);
                page.await("document.querySelectorAll('.row[data-state=ended]').length === 9", "the ended runs", 30);
                page.await("document.querySelectorAll('.row[data-stale=true]').length === 5", "the stale ones", 30);
                JsonNode fit = JSON.readTree(page.eval("JSON.stringify({w: innerWidth, h: innerHeight,"
                        + " scroll: document.documentElement.scrollHeight, outside: [...document.querySelectorAll('.row')]"
                        + ".filter(r => { const b = r.getBoundingClientRect(); return b.top < 0 || b.left < 0"
                        + " || b.bottom > innerHeight || b.right > innerWidth; }).map(r => r.dataset.log),"
                        + " states: [...document.querySelectorAll('.row')].map(r => r.dataset.state)})"));
                assertEquals(WIDTH, fit.get("w").asInt());
                assertEquals(HEIGHT, fit.get("h").asInt());
                assertEquals(0, fit.get("outside").size(), "rows off the screen: " + fit.get("outside"));
                assertTrue(fit.get("scroll").asInt() <= HEIGHT, "the page does not scroll: " + fit);
                List<String> states = new ArrayList<>();
                fit.get("states").forEach(s -> states.add(s.asText()));
                assertEquals(List.of("violation", "violation", "violation", "violation"), states.subList(0, 4),
                        "worst first: " + states);
                assertEquals("ended", states.get(99));
                BrowserTabs.screenshot(page, "live-compact.png", DOCUMENTED);

                click(page, "document.getElementById('view')");
                page.await("document.querySelectorAll('#tiles.tiles article.tile').length === 100", "the tiles", 30);
                assertFalse(page.eval("location.search").contains("compact"));
            }
        }
    }

    /** A fleet as an operator sees it in the full view: every state at once (the documentation's screenshot). */
    @Test
    @Timeout(240)
    void aFleetInEveryState() throws Exception {
        Path models = ForecastModels.get();
        String depleted = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        long[] at = lines(Files.writeString(dir.resolve("full.log"), depleted), models);
        Cli sim = Cli.run("simulate", "--scenario", "direct", "--seed", "5", "--aborts", "2", "--out",
                dir.resolve("blocked.log").toString());
        assertEquals(0, sim.code(), sim.err());
        String blocked = Files.readString(dir.resolve("blocked.log"));
        String recharge = FleetWatchTest.run(Scenario.RECHARGE, 9002);
        List<Path> live = List.of(robot("r2", head(depleted, (at[0] + at[1]) / 2)),
                robot("r3", head(blocked, blocked.lines().count() * 3 / 4)), robot("r4", head(recharge, 6000)));
        List<Path> quiet = List.of(robot("r1", depleted), robot("r5", FleetWatchTest.run(Scenario.DIRECT, 9003)));
        try (LiveScene scene = new LiveScene(models, Duration.ofSeconds(3), RobotNames.pattern("{dir}"),
                List.of("logs in robots"))) {
            for (Path p : quiet) {
                scene.follow(p);
            }
            List<Tile> tiles = new ArrayList<>();
            for (Path p : live) {
                tiles.add(scene.follow(p));
            }
            scene.board.tile(dir.resolve("robots/r6/monitor.log").toString());
            try (AutoCloseable growing = scene.growing(tiles)) {
                HeadlessChromium.Page page = open(scene.url());
                page.await("document.querySelectorAll('article.tile').length === 6", "six tiles", 30);
                page.await("document.querySelector('[data-state=ended]') !== null", "r5's run ended", 30);
                List<String> states = new ArrayList<>();
                JSON.readTree(page.eval("JSON.stringify([...document.querySelectorAll('article.tile')]"
                        + ".map(t => t.dataset.state))")).forEach(s -> states.add(s.asText()));
                // r3's aborts violate no-abort: the robot's state is that violation, its worst property's; its
                // battery's own state, no model matching the run, is unknown
                assertEquals(List.of("violation", "violation", "warning", "ok", "waiting", "ended"), states);
                assertEquals("unknown", page.eval("document.querySelectorAll('article.tile')[1]"
                        + ".querySelector('li.prop[data-property=battery]').dataset.state"));
                ObjectNode ticks = (ObjectNode) JSON.readTree(page.eval("JSON.stringify({x: [...document"
                        + ".querySelectorAll('article.tile')[0].querySelectorAll('svg.plot text.axis')].length})"));
                assertTrue(ticks.get("x").asInt() >= 8, "several labelled ticks on the axes: " + ticks);
                assertEquals("0", page.eval("String([...document.querySelectorAll('.events li')].filter(li =>"
                        + " getComputedStyle(li).textOverflow === 'ellipsis').length)"), "no event is cut off");
                BrowserTabs.screenshot(page, "live-fleet.png", DOCUMENTED);
            }
        }
    }
}
