package dev.predmon.support;

import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The one headless Chromium of a browser test class, as a JUnit extension: registered on a static field
 * ({@code @RegisterExtension static final BrowserTabs TABS = new BrowserTabs();}), it starts the browser before the
 * class's tests, closes the tabs each test opened after it (so that none keeps polling a server that is gone), and
 * closes the browser after the class. Without Chromium a test that asks for a tab is skipped, with a message saying
 * what is not tested. The page's server is the test's: {@link LiveWatch} for {@code watch --http}.
 */
public final class BrowserTabs implements BeforeAllCallback, AfterEachCallback, AfterAllCallback {

    /** The screen the page is looked at on, unless a test gives another. */
    public static final int WIDTH = 1920;
    public static final int HEIGHT = 1080;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final int width;
    private final int height;
    private final List<HeadlessChromium.Page> pages = new ArrayList<>();
    private HeadlessChromium browser;

    /** Tabs at a 1920x1080 screen. */
    public BrowserTabs() {
        this(WIDTH, HEIGHT);
    }

    /** Tabs at a screen of this size. */
    public BrowserTabs(int width, int height) {
        this.width = width;
        this.height = height;
    }

    @Override
    public void beforeAll(ExtensionContext context) throws Exception {
        Optional<Path> chromium = HeadlessChromium.find();
        browser = chromium.isPresent() ? HeadlessChromium.start(chromium.get(), width, height) : null;
    }

    @Override
    public void afterEach(ExtensionContext context) throws Exception {
        for (HeadlessChromium.Page p : pages) {
            p.call("Page.close", JSON.createObjectNode());
        }
        pages.clear();
    }

    @Override
    public void afterAll(ExtensionContext context) throws Exception {
        if (browser != null) {
            browser.close();
            browser = null;
        }
    }

    /** Skips the test without Chromium, {@code untested} saying what is not tested. */
    public void assumeBrowser(String untested) {
        assumeTrue(browser != null, "no Chromium found (apt-get install chromium, or -Dpredmon.chromium=PATH): "
                + untested);
    }

    /** A blank tab at the screen's size; without Chromium the test is skipped, {@code untested} saying what is not. */
    public HeadlessChromium.Page blank(String untested) throws Exception {
        assumeBrowser(untested);
        HeadlessChromium.Page page = browser.open(URI.create("about:blank"));
        pages.add(page);
        page.call("Emulation.setDeviceMetricsOverride", JSON.createObjectNode().put("width", width)
                .put("height", height).put("deviceScaleFactor", 1).put("mobile", false));
        return page;
    }

    /** A tab at the screen's size showing {@code url}; skipped without Chromium, as {@link #blank}. */
    public HeadlessChromium.Page open(URI url, String untested) throws Exception {
        HeadlessChromium.Page page = blank(untested);
        page.call("Page.navigate", JSON.createObjectNode().put("url", url.toString()));
        return page;
    }

    /**
     * Saves what {@code page} shows as {@code target/NAME}, and, when {@code NAME} is one of {@code documented}, into
     * the directory {@code -Dpredmon.screenshots=DIR} gives (the documentation's screenshots are made so).
     */
    public static void screenshot(HeadlessChromium.Page page, String name, Set<String> documented) throws Exception {
        page.screenshot(Path.of("target", name));
        String docs = System.getProperty("predmon.screenshots");
        if (docs != null && !docs.isBlank() && documented.contains(name)) {
            page.screenshot(Path.of(docs, name));
        }
    }
}
