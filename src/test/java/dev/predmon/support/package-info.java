/**
 * What tests of several packages share: hand-built and simulated runs, the real recordings when they are present,
 * decisions for fuzz targets, the one headless Chromium of a browser test class ({@link dev.predmon.support.BrowserTabs})
 * and the {@code watch --http} it looks at ({@link dev.predmon.support.LiveWatch}).
 */
package dev.predmon.support;
