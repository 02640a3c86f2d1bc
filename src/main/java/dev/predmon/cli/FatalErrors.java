package dev.predmon.cli;

import dev.predmon.Terminal;

import java.io.PrintStream;

/**
 * Reports a Java {@link Error} (out of memory, a stack overflow, a class that did not load) as one line and exit
 * {@value ExitCodes#INTERNAL}, the stack trace only with {@code --verbose}: on the main thread, where picocli lets
 * it pass, and as the handler of every other thread's uncaught throwable, which then ends the process rather than
 * leave it running without that thread.
 *
 * <p>It must work with the heap exhausted: it holds a reserve of memory that it lets go before it does anything,
 * and builds its line without string concatenation (whose first use links code at run time, which allocates).
 */
final class FatalErrors implements Thread.UncaughtExceptionHandler {

    private static final String PREFIX = "predmon: internal error: ";
    private static final String DETAILS = " (rerun with --verbose for details)";

    private final PrintStream err;
    private final boolean verbose;
    @SuppressWarnings("unused") // held only to be let go when the heap is exhausted
    private byte[] reserve = new byte[1 << 18];

    FatalErrors(PrintStream err, boolean verbose) {
        this.err = err;
        this.verbose = verbose;
    }

    /** Prints the one line (and with {@code --verbose} the stack trace); returns the exit code. */
    int report(Throwable e) {
        reserve = null;
        StringBuilder b = new StringBuilder(PREFIX);
        if (e instanceof OutOfMemoryError) {
            b.append("out of memory (").append(e.getMessage()).append("); give Java more heap with -Xmx");
        } else if (e instanceof StackOverflowError) {
            b.append("the call stack overflowed (an input nested far too deep?)");
        } else {
            b.append(Terminal.line(String.valueOf(e)));
        }
        if (!verbose) {
            b.append(DETAILS);
        }
        err.println(b);
        if (verbose) {
            e.printStackTrace(err);
        }
        err.flush();
        return ExitCodes.INTERNAL;
    }

    /** Another thread's uncaught Error ends the process; an exception is printed as the JVM would. */
    @Override
    public void uncaughtException(Thread t, Throwable e) {
        if (e instanceof Error) {
            System.exit(report(e));
        }
        err.print("Exception in thread \"" + t.getName() + "\" ");
        e.printStackTrace(err);
    }
}
