package dev.predmon.watch;

import dev.predmon.Terminal;
import dev.predmon.pipeline.UnmappedMessages;

import java.io.IOException;
import java.io.PrintWriter;
import java.math.BigDecimal;
import java.nio.file.Path;

/**
 * What a watch session says on stderr besides parse problems, one line each and flushed at once: that a log is
 * followed, interface messages no rule maps at their first sighting, why a log gets no verdict, logs that cannot be
 * read or found, and where file-change notification is unavailable.
 */
final class Notices {

    private final PrintWriter err;
    private String lastRescanFailure;

    Notices(PrintWriter err) {
        this.err = err;
    }

    /** One line, {@code predmon: } and {@code what}. */
    void say(String what) {
        err.println(Terminal.line("predmon: " + what));
        err.flush();
    }

    /**
     * While following, the first message of a command no rule maps, with its line, for at most
     * {@value UnmappedMessages#MAX_LINES} commands (one line per pose value would bury everything else), then one line
     * that there are more. With {@code --no-follow} the totals by command at the end say it all.
     *
     * @param commands how many commands have been seen so far, this one included
     */
    void unmapped(String log, long line, String message, int commands) {
        err.println(Terminal.line(log + ":" + line + ": warning: " + (commands > UnmappedMessages.MAX_LINES
                ? "more commands no abstraction rule maps; the totals come at the stop"
                : "interface message no abstraction rule maps: " + message + " (first of its command; the totals "
                + "come at the stop)")));
        err.flush();
    }

    /** Looking for new logs failed: said once, not every second. */
    void rescanFailed(IOException e) {
        String message = "looking for new logs: " + e.getMessage();
        if (!message.equals(lastRescanFailure)) {
            say(message);
            lastRescanFailure = message;
        }
    }

    /** What cannot be notified, why, and that it is polled instead, how often. */
    void unnotified(Path dir, String why, long pauseNanos) {
        String every = BigDecimal.valueOf(pauseNanos, 6).stripTrailingZeros().toPlainString() + " ms";
        say("file-change notification unavailable" + (dir == null ? "" : " for " + dir) + " (" + why + "); polling "
                + (dir == null ? "every log" : "its logs") + " every " + every);
    }
}
