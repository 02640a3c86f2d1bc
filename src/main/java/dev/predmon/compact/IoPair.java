package dev.predmon.compact;

import dev.predmon.parse.LogRecord;

/**
 * A query of the interface with its answer, after compaction: one step of the I/O-automaton trace.
 *
 * @param input   the command's input symbol
 * @param output  the reply's output symbol
 * @param command the command record
 * @param reply   the reply record
 */
public record IoPair(String input, String output, LogRecord command, LogRecord reply) {
}
