package dev.predmon.cli;

import dev.predmon.live.RobotNames;
import dev.predmon.live.Tile;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HandRuns;
import dev.predmon.support.HeadlessChromium;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The live page's header counts the robots by state in words that agree with their number, in a real browser
 * (headless Chromium): "1 violation", then "2 violations" once a second robot's battery is violated. Skipped, with
 * a message, without Chromium.
 */
class LiveSummaryBrowserTest {

    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs();

    @TempDir
    Path dir;

    private static String summary(HeadlessChromium.Page page) throws Exception {
        return page.eval("(document.getElementById('summary') || {}).textContent || ''");
    }

    /** The header once it reads {@code expected}, or the assertion error with what it read after 30 s. */
    private static void awaitSummary(HeadlessChromium.Page page, String expected) throws Exception {
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (!summary(page).equals(expected) && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        assertEquals(expected, summary(page));
    }

    @Test
    @Timeout(120)
    void theHeaderSaysTwoViolationsInThePlural() throws Exception {
        try (LiveScene scene = new LiveScene(Path.of("models"), Duration.ofMinutes(10), RobotNames.pattern("{file}"),
                List.of())) {
            // the hand-written depleted run: its battery reads 18 at t=80, below the floor of 20
            Tile r1 = scene.board.tile(dir.resolve("r1.log").toString());
            scene.feed(r1, HandRuns.depleted().list());
            Tile r2 = scene.board.tile(dir.resolve("r2.log").toString());
            scene.feed(r2, HandRuns.recharge().list()); // a run no learned model matches: unknown

            HeadlessChromium.Page page = TABS.open(scene.url(), "the live page's header is not tested in a browser");
            awaitSummary(page, "2 robots: 1 violation, 1 unknown");

            Tile r3 = scene.board.tile(dir.resolve("r3.log").toString());
            scene.feed(r3, HandRuns.depleted().list());
            awaitSummary(page, "3 robots: 2 violations, 1 unknown");
            assertTrue(page.eval("document.title").startsWith("VIOLATION"), page.eval("document.title"));
        }
    }
}
