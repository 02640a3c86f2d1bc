/**
 * A watch session: follows logs into monitors and sends each event to stdout, the live page and the hook commands;
 * holds the verdict, the exit rules ({@link dev.predmon.watch.ExitRule}) and the end summary. {@code watch} and
 * {@code demo} run one; {@code classify} and {@code explain} give its exit code.
 */
package dev.predmon.watch;
