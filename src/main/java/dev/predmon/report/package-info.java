/**
 * Renders an {@code evaluate} result as one self-contained HTML page: tables, charts and the learned machines drawn.
 */
package dev.predmon.report;
