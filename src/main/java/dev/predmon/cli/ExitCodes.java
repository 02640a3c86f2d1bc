package dev.predmon.cli;

/** Exit codes of every predmon command (documented in the README). */
public final class ExitCodes {
    /** Success; for watch/classify: no warning. */
    public static final int OK = 0;
    /** watch/classify: a warning was raised (the run is predicted faulty); verify: the log does not match. */
    public static final int WARNING = 1;
    /** Bad usage: unknown option, missing argument (picocli's own code). */
    public static final int USAGE = 2;
    /** Bad input: a log, model directory, abstraction or scenario file that cannot be used. */
    public static final int BAD_INPUT = 3;
    /** A bug in predmon; rerun with --verbose for the stack trace. */
    public static final int INTERNAL = 4;

    private ExitCodes() {
    }
}
