package dev.predmon.cli;

import sun.misc.Signal;
import sun.misc.SignalHandler;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * While {@code watch} follows a log, SIGINT (Ctrl-C), SIGTERM and SIGHUP interrupt the following thread instead of
 * ending the JVM (exit 130, 143 or 129, no summary): watch then stops as after any interrupt, prints its summary and
 * exits per the exit-code table. SIGHUP is a stop like SIGTERM: it is what a closed terminal or SSH session sends,
 * and a watch that dies of it without its summary loses the verdict of every run it followed. The previous handlers are restored on {@link #close()}. A signal that was ignored when the
 * JVM started (a background job of a script ignores SIGINT) stays ignored, and where the JVM keeps the signals to
 * itself ({@code -Xrs}) nothing changes.
 *
 * <p>{@code sun.misc.Signal} (module {@code jdk.unsupported}) is the only way in Java 17 to handle a signal
 * without starting the JVM's shutdown, which cannot change the exit code.
 */
final class StopSignals implements AutoCloseable {

    private static final List<String> STOP = List.of("INT", "TERM", "HUP");

    private final Map<Signal, SignalHandler> previous = new LinkedHashMap<>();
    private volatile String received;

    private StopSignals() {
    }

    /** From now until {@link #close()}, SIGINT, SIGTERM and SIGHUP interrupt {@code thread}. */
    static StopSignals interrupting(Thread thread) {
        StopSignals s = new StopSignals();
        for (String name : STOP) {
            Signal signal = new Signal(name);
            try {
                s.previous.put(signal, Signal.handle(signal, sig -> {
                    s.received = "SIG" + sig.getName();
                    thread.interrupt();
                }));
            } catch (IllegalArgumentException e) {
                // the JVM keeps this signal (-Xrs): its default stays
            }
        }
        return s;
    }

    /** The signal that stopped watching ({@code SIGINT}, {@code SIGTERM}, {@code SIGHUP}), or null. */
    String received() {
        return received;
    }

    @Override
    public void close() {
        previous.forEach(Signal::handle);
    }
}
