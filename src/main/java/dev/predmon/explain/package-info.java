/**
 * Explains one run for {@code explain}: where each model stopped matching it, and what the monitor concluded.
 */
package dev.predmon.explain;
