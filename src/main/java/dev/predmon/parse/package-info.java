/**
 * Reads YARP monitor logs in each of their layouts (yarplogger's columns and save file, the monitor's
 * redirected console output), whole or followed as they grow, into {@link LogRecord}s and the problems met on the
 * way.
 */
package dev.predmon.parse;
