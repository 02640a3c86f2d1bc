package dev.predmon.cli;

import dev.predmon.evaluate.Progress;

import java.io.Console;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A one-line progress indicator on stderr ({@code [ 12/40] fold 1: run-7.log}), redrawn in place with a carriage
 * return, for terminals only: a redirected stderr gets nothing, so logs and CI output stay clean.
 */
final class ProgressBar implements Progress {

    private final PrintWriter err;
    private long last;
    private int width;

    private ProgressBar(PrintWriter err) {
        this.err = err;
    }

    /** A progress bar on {@code err}, or {@link Progress#NONE} when quiet or stderr is not a terminal. */
    static Progress on(PrintWriter err, boolean quiet) {
        return quiet || !stderrIsTerminal() ? NONE : new ProgressBar(err);
    }

    /**
     * Java has no isatty; on Linux stderr's descriptor links to a {@code /dev/pts/N} or {@code /dev/ttyN} device
     * when it is a terminal. Elsewhere fall back to {@link System#console()} (stdin and stdout are terminals).
     */
    static boolean stderrIsTerminal() {
        Path fd = Path.of("/proc/self/fd/2");
        try {
            if (Files.isSymbolicLink(fd)) {
                String target = Files.readSymbolicLink(fd).toString();
                return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
            }
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return consoleIsTerminal();
        }
        return consoleIsTerminal();
    }

    /**
     * Whether stdin and stdout are a terminal. Up to JDK 21 {@link System#console()} is null when they are not; from
     * JDK 22 on it returns a console all the same, and the console's {@code isTerminal()} (new in JDK 22) says.
     */
    // A null console is the answer of JDK 21 and before; JDK 22 and later are asked isTerminal() below.
    @SuppressWarnings("SystemConsoleNull")
    private static boolean consoleIsTerminal() {
        Console console = System.console();
        if (console == null) {
            return false;
        }
        try {
            return (Boolean) Console.class.getMethod("isTerminal").invoke(console);
        } catch (ReflectiveOperationException beforeJdk22) {
            return true; // up to JDK 21 there is a console only for a terminal
        }
    }

    @Override
    public void step(int done, int total, String what) {
        long now = System.nanoTime();
        boolean end = done >= total;
        if (!end && now - last < 100_000_000L) {
            return; // redrawing more than ten times a second only costs time
        }
        last = now;
        String text = String.format("[%" + Integer.toString(total).length() + "d/%d] %s", done, total, what);
        if (text.length() > 100) {
            text = text.substring(0, 100);
        }
        err.print("\r" + text + " ".repeat(Math.max(0, width - text.length())));
        width = text.length();
        if (end) {
            err.print("\r" + " ".repeat(width) + "\r");
        }
        err.flush();
    }
}
