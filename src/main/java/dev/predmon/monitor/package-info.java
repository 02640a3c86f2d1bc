/**
 * The predictive monitor: runs every learned model along a trace, offline or record by record while logs grow
 * (a whole fleet of logs on one thread), and warns before the safety property is violated.
 */
package dev.predmon.monitor;
