/**
 * Which learned machines still match a run, pair by pair, and the thesis's rule over them (Algorithm 8): one
 * implementation that {@code watch} follows live and {@code learn} replays on held-out runs.
 */
package dev.predmon.matching;
