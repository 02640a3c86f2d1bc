package dev.predmon.monitor;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** How the names given to {@code watch --log} become the logs of a fleet. */
class LogSourcesTest {

    @TempDir
    Path dir;

    private Path file(String relative) throws Exception {
        Path p = dir.resolve(relative);
        Files.createDirectories(p.getParent());
        return Files.writeString(p, "x");
    }

    @Test
    void aFileIsWatchedBeforeItExistsAndADirectoryGivesItsLogsSorted() throws Exception {
        Path missing = dir.resolve("later.log");
        Path b = file("d/b.log");
        Path a = file("d/a.txt");
        file("d/a.log.truth.json");
        file("d/sub/deeper.log");
        LogSources s = new LogSources(List.of(missing, dir.resolve("d")));
        assertEquals(List.of(missing, a, b), s.find());
        assertTrue(s.several() && s.growing());
        Path c = file("d/c.log");
        assertEquals(List.of(missing, a, b, c), s.find(), "a log that appears later is found at the next look");
    }

    @Test
    void aGlobMatchesBelowItsFixedDirectoriesAndAnyDepthWithTwoStars() throws Exception {
        Path r1 = file("robots/r1/monitor.log");
        Path r2 = file("robots/r2/monitor.log");
        file("robots/r2/other.log");
        Path deep = file("robots/r3/x/monitor.log");
        assertEquals(List.of(r1, r2), new LogSources(List.of(dir.resolve("robots/*/monitor.log"))).find());
        assertEquals(List.of(r1, r2, deep), new LogSources(List.of(dir.resolve("robots/**/monitor.log"))).find());
        assertEquals(List.of(), new LogSources(List.of(dir.resolve("nowhere/*.log"))).find());
    }

    /** A file whose name has glob characters is that file; a name that is neither is one line naming it. */
    @Test
    void anExistingNameIsAFileEvenWithGlobCharactersInIt() throws Exception {
        Path odd = file("robot[1.log");
        LogSources s = new LogSources(List.of(odd));
        assertEquals(List.of(odd), s.find());
        assertFalse(s.several(), "one file, not a glob");
        IOException e = assertThrows(IOException.class,
                () -> new LogSources(List.of(dir.resolve("robot[2.log"))).find());
        assertEquals(dir.resolve("robot[2.log") + ": no such file, and not a valid glob", e.getMessage());
    }

    @Test
    void aDirectoryThatGoesAwayStaysADirectoryAndIsLookedIntoWhenItIsBack() throws Exception {
        Path d = Files.createDirectories(dir.resolve("d"));
        LogSources s = new LogSources(List.of(d));
        Files.delete(d);
        assertEquals(List.of(), s.find(), "not taken for a log file named d");
        assertEquals(List.of("logs in " + d), s.missing());
        Path back = file("d/r.log");
        assertEquals(List.of(back), s.find());
        assertTrue(s.several());
    }

    @Test
    void aLogNamedTwiceIsWatchedOnce() throws Exception {
        Path a = file("a.log");
        LogSources s = new LogSources(List.of(a, dir.resolve("./a.log"), dir.resolve("*.log")));
        assertEquals(List.of(a), s.find());
    }

    /**
     * A {@code latest.log} link beside the log it points to, and a hard link: one file, one robot, followed by its
     * own name (two names gave two tiles, two warnings and two hook runs).
     */
    @Test
    void aFileWithSeveralNamesIsWatchedOnceByItsOwnName() throws Exception {
        Path run = file("robots/run-0005.log");
        Path other = file("robots/robot-2.log");
        Files.createSymbolicLink(dir.resolve("robots/latest.log"), Path.of("run-0005.log"));
        LogSources s = new LogSources(List.of(dir.resolve("robots")));
        assertEquals(List.of(other, run), s.find());
        assertEquals(List.of(other, run), new LogSources(List.of(dir.resolve("robots/*.log"))).find());
        Files.createLink(dir.resolve("robots/copy.log"), other);
        assertEquals(List.of(other, run), s.find(), "a hard link: the first name");
        Path elsewhere = file("archive/run-0001.log");
        Path outside = Files.createSymbolicLink(dir.resolve("robots/old.log"), elsewhere);
        assertEquals(List.of(outside, other, run), s.find(), "a link to a file not otherwise watched is followed");
        Files.delete(dir.resolve("robots/copy.log"));
        Path named = dir.resolve("robots/latest.log");
        assertEquals(List.of(named, outside, other), new LogSources(List.of(named, dir.resolve("robots"))).find(),
                "a link named as the log is followed by that name, and its target not again");
    }

    @Test
    void oneFileIsNotSeveralEvenIfAGlobCouldBe() throws Exception {
        Path a = file("a.log");
        assertFalse(new LogSources(List.of(a)).several(), "events keep their single-log shape");
        assertFalse(new LogSources(List.of(a)).growing());
        assertTrue(new LogSources(List.of(dir.resolve("a*.log"))).several(),
                "decided by the name, not by how many files match it now");
    }

    @Test
    void theDirectoriesWatchedForNewLogsAreTheNamedOnesAndThoseAGlobReaches() throws Exception {
        Path a = file("robots/r1/monitor.log");
        file("robots/r2/x/monitor.log");
        Path d = Files.createDirectories(dir.resolve("d"));
        Path gone = Files.createDirectories(dir.resolve("gone"));
        Path robots = dir.resolve("robots");
        LogSources s = new LogSources(List.of(a, d, gone, robots.resolve("*/monitor.log")));
        Files.delete(gone);
        assertEquals(Set.of(d, gone, robots, robots.resolve("r1"), robots.resolve("r2")), Set.copyOf(s.directories()),
                "a named file is not listed (its own directory is watched with it); a directory gone is");
        assertEquals(Set.of(robots, robots.resolve("r1"), robots.resolve("r2"), robots.resolve("r2/x")),
                Set.copyOf(new LogSources(List.of(robots.resolve("**/monitor.log"))).directories()));
    }

    /**
     * A look at a directory of 10,000 followed logs was a stat of each (15% of a core at robot pace): a log the last
     * look listed is taken from the listing as it is, and only a new file is looked at.
     */
    @Test
    void aLookStatsOnlyTheFilesTheLastLookDidNotList() throws Exception {
        Path a = file("d/a.log");
        Path b = file("d/b.log");
        file("d/notes.md");
        LogSources s = new LogSources(List.of(dir.resolve("d")));
        assertEquals(List.of(a, b), s.findNew());
        long first = s.stats();
        assertEquals(3, first, "each entry once: a.log, b.log, notes.md");
        assertEquals(List.of(), s.findNew(), "nothing new");
        assertEquals(first + 1, s.stats(), "notes.md is no log yet and looked at again; a.log and b.log are not");
        Path c = file("d/c.log");
        assertEquals(List.of(c), s.findNew());
        assertEquals(first + 3, s.stats(), "c.log and notes.md");
        assertEquals(List.of(a, b, c), s.find(), "a full look still lists every log");
        Files.delete(b);
        assertEquals(List.of(), s.findNew());
        file("d/b.log");
        assertEquals(List.of(b), s.findNew(), "a log gone at one look and back at the next is new");
    }

    /** A rotation renames a followed log to another log's name and creates a new one: two files, two logs. */
    @Test
    void aLogRenamedAwayAndCreatedAgainIsTwoFiles() throws Exception {
        Path log = file("d/robot.log");
        LogSources s = new LogSources(List.of(dir.resolve("d")));
        assertEquals(List.of(log), s.findNew());
        Path old = dir.resolve("d/robot-1.log");
        Files.move(log, old);
        file("d/robot.log");
        assertEquals(List.of(old), s.findNew(), "robot-1.log holds the file robot.log was: robot.log is looked at"
                + " again, and is another file now");
        assertEquals(List.of(old, log), s.find());
    }

    @Test
    void aLogTheFleetForgotIsNewAgain() throws Exception {
        Path a = file("d/a.log");
        LogSources s = new LogSources(List.of(dir.resolve("d")));
        assertEquals(List.of(a), s.findNew());
        assertEquals(List.of(), s.findNew());
        s.forget(a);
        assertEquals(List.of(a), s.findNew());
    }
}
