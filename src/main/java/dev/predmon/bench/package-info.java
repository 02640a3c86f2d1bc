/**
 * The measurements behind {@code predmon bench}: batch throughput, append-to-warning latency, memory on an
 * endless log, learning time and heap, and a fleet of logs watched in one process.
 */
package dev.predmon.bench;
