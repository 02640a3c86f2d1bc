package dev.predmon.watch;

import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * When {@code watch} must poll because the operating system's file-change notification is unavailable (for every
 * log, or for one directory), it says so in one line on stderr: what, why, and how often it polls instead. The fleet
 * tells each case once ({@code WakeupsTest}); this is the line.
 */
class UnnotifiedLineTest {

    @Test
    void oneLineSaysWhatWhyAndHowOften() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        try (WatchSession outputs = new WatchSession(new PrintWriter(out), new PrintWriter(err),
                WatchSettings.of(false, false, true, false), null, null, AbstractionFiles.defaults(), p -> false)) {
            outputs.unnotified(null, "User limit of inotify instances reached or too many open files",
                    TimeUnit.MILLISECONDS.toNanos(2));
            outputs.unnotified(Path.of("/mnt/robots"), "network or FUSE file system, whose changes on other hosts "
                    + "are not notified", TimeUnit.MICROSECONDS.toNanos(500));
            outputs.unnotified(Path.of("/logs/\u001b[2Jx"), "permission denied", TimeUnit.SECONDS.toNanos(1));
        }
        assertEquals(String.join(System.lineSeparator(),
                "predmon: file-change notification unavailable (User limit of inotify instances reached or too many "
                        + "open files); polling every log every 2 ms",
                "predmon: file-change notification unavailable for /mnt/robots (network or FUSE file system, whose "
                        + "changes on other hosts are not notified); polling its logs every 0.5 ms",
                "predmon: file-change notification unavailable for /logs/\\x1b[2Jx (permission denied); polling its "
                        + "logs every 1000 ms", ""), err.toString());
        assertEquals("", out.toString());
    }
}
