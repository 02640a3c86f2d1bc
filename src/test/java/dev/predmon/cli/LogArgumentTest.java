package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A {@code --log} that is a directory, missing or unreadable gets the same one line, naming it, from watch, verify,
 * classify and explain (they share one option mixin, {@link LogAgainstModels}).
 */
class LogArgumentTest {

    @TempDir
    Path tmp;
    Path models;

    @BeforeEach
    void learn() throws Exception {
        Path logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(logs, models, "recharge");
    }

    /** The four commands' arguments for {@code log}. */
    private List<String[]> commands(Path log) {
        List<String[]> all = new ArrayList<>();
        String l = log.toString();
        String m = models.toString();
        all.add(new String[] {"watch", "--no-follow", "--log", l, "--models", m});
        all.add(new String[] {"verify", "--scenario", "depleted", "--log", l, "--models", m});
        all.add(new String[] {"classify", "--log", l, "--models", m});
        all.add(new String[] {"explain", "--log", l, "--models", m});
        return all;
    }

    /** Every command: exit 3, nothing on stdout, and one stderr line, the same from all four. */
    private static void sameLine(List<Cli> runs, String expected) {
        for (Cli r : runs) {
            assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
            assertEquals("", r.out());
            assertEquals(List.of("predmon: " + expected), r.err().strip().lines().toList());
        }
    }

    /** verify, classify and explain judge one log: a directory is refused with one line, the same from all three. */
    @Test
    void aDirectory() {
        Path dir = tmp.resolve("logs");
        sameLine(commands(dir).stream().filter(a -> !a[0].equals("watch")).map(Cli::run).toList(),
                dir + ": is a directory; expected a log file or a ROS 2 recording");
    }

    @Test
    void aMissingFile() {
        Path missing = tmp.resolve("missing.log");
        sameLine(commands(missing).stream().map(Cli::run).toList(), missing + ": no such file; expected a log file");
    }

    /**
     * watch follows the logs of a directory (a fleet, issue 11); one pass over a directory that holds no log is
     * refused with one line that says so.
     */
    @Test
    void watchTakesADirectoryAsItsLogsAndRefusesOneWithout() throws Exception {
        Path empty = Files.createDirectories(tmp.resolve("no-logs-here"));
        Cli r = Cli.run("watch", "--no-follow", "--log", empty.toString(), "--models", models.toString());
        sameLine(List.of(r), empty + ": is a directory with no log file (*.log, *.txt) in it");
    }

    /** Unreadable: in real processes, since permissions do not bind root (dropped with setpriv there). */
    @Test
    void anUnreadableFile() throws Exception {
        Path log = Files.writeString(tmp.resolve("secret.log"), HandRuns.depleted().text());
        Files.setPosixFilePermissions(log, PosixFilePermissions.fromString("---------"));
        Files.setPosixFilePermissions(tmp, PosixFilePermissions.fromString("rwxr-xr-x"));
        try {
            List<Cli> runs = new ArrayList<>();
            for (String[] args : commands(log)) {
                Child c = Child.runBoundByPermissions(tmp, args);
                runs.add(new Cli(c.code(), c.out(), c.err()));
            }
            sameLine(runs, log + ": permission denied; expected a readable log file");
            for (Cli r : runs) {
                assertFalse(r.err().contains("Exception") || r.err().contains("java."), r.err());
            }
        } finally {
            Files.setPosixFilePermissions(log, PosixFilePermissions.fromString("rw-r--r--"));
        }
        assertTrue(Files.isReadable(log));
    }
}
