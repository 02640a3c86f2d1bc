package dev.predmon.support;

import com.fasterxml.jackson.databind.ObjectMapper;

import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * One headless Chromium at a 1920x1080 screen for a test class, and the tabs its tests open, closed after each test
 * so that none keeps polling a server that is gone. Without Chromium a test that asks for a tab is skipped.
 */
public final class BrowserTabs implements AutoCloseable {

    /** The screen the page is looked at on. */
    public static final int WIDTH = 1920;
    public static final int HEIGHT = 1080;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final HeadlessChromium browser;
    private final List<HeadlessChromium.Page> pages = new ArrayList<>();

    private BrowserTabs(HeadlessChromium browser) {
        this.browser = browser;
    }

    /** Starts Chromium when there is one; tabs are then refused with a skip. */
    public static BrowserTabs start() throws Exception {
        Optional<Path> chromium = HeadlessChromium.find();
        return new BrowserTabs(chromium.isPresent() ? HeadlessChromium.start(chromium.get(), WIDTH, HEIGHT) : null);
    }

    /** A blank tab at the screen's size; without Chromium the test is skipped, {@code untested} saying what is not. */
    public HeadlessChromium.Page blank(String untested) throws Exception {
        assumeTrue(browser != null, "no Chromium found (apt-get install chromium, or -Dpredmon.chromium=PATH): "
                + untested);
        HeadlessChromium.Page page = browser.open(URI.create("about:blank"));
        pages.add(page);
        page.call("Emulation.setDeviceMetricsOverride", JSON.createObjectNode().put("width", WIDTH)
                .put("height", HEIGHT).put("deviceScaleFactor", 1).put("mobile", false));
        return page;
    }

    /** A tab at the screen's size showing {@code url}; skipped without Chromium, as {@link #blank}. */
    public HeadlessChromium.Page open(URI url, String untested) throws Exception {
        HeadlessChromium.Page page = blank(untested);
        page.call("Page.navigate", JSON.createObjectNode().put("url", url.toString()));
        return page;
    }

    /** Closes the tabs opened since the last call. */
    public void closeTabs() throws Exception {
        for (HeadlessChromium.Page p : pages) {
            p.call("Page.close", JSON.createObjectNode());
        }
        pages.clear();
    }

    @Override
    public void close() throws Exception {
        if (browser != null) {
            browser.close();
        }
    }
}
