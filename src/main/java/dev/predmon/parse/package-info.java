/**
 * Reads YARP monitor logs in each of their layouts (yarplogger's columns and save file, the monitor's
 * redirected console output), whole or followed as they grow, into {@link LogRecord}s and the problems met on the
 * way. The stages above see an input format only as a {@link LogFormat} whose {@link RecordSource}s deliver to a
 * {@link RecordSink}; {@link LogFormat#yarp()} is the one there is.
 */
package dev.predmon.parse;
