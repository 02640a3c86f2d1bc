/**
 * What tests of several packages share: hand-built and simulated runs, the real recordings when they are present,
 * decisions for fuzz targets, and the one headless Chromium that the browser tests drive.
 */
package dev.predmon.support;
