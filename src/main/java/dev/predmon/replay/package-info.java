/**
 * The one replay of a log: a complete file read through {@code watch}'s own monitor, and per run the ordered stream
 * of what it made of it (pairs, gaps, forecasts, events with their warnings and verdicts). {@code learn}'s held-out
 * forecasts, {@code evaluate}, {@code explain}, {@code classify} and {@code watch --no-follow} all judge a log
 * through it, so that they cannot disagree.
 */
package dev.predmon.replay;
