package dev.predmon.monitor;

import dev.predmon.parse.LogFollower;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;

/** How the chaos soak's robots write their logs, and what is done to a log between two runs. */
final class ChaosWriter {

    private ChaosWriter() {
    }

    /** What is done to a log before its next run is written. */
    enum Chaos {
        RENAME, RENAME_TWICE_EMPTY, RENAME_WHILE_WRITTEN, RENAME_PAUSED_WRITTEN, COPYTRUNCATE, TRUNCATE, DELETE, FIFO,
        DIRECTORY
    }

    static void apply(Chaos chaos, Path log, String name, int n) throws Exception {
        Path rotated = log.resolveSibling(name + "." + n);
        switch (chaos) {
            case RENAME, RENAME_PAUSED_WRITTEN -> {
                Files.move(log, rotated);
                Files.writeString(log, "");
            }
            case RENAME_TWICE_EMPTY -> {
                Files.move(log, rotated);
                Files.writeString(log, "");
                Thread.sleep(100);
                Files.move(log, log.resolveSibling(name + "." + n + "b"));
                Files.writeString(log, "");
            }
            case RENAME_WHILE_WRITTEN -> {
                Files.move(log, rotated);
            }
            case COPYTRUNCATE -> {
                Files.copy(log, rotated, StandardCopyOption.REPLACE_EXISTING);
                truncate(log);
            }
            case TRUNCATE -> truncate(log);
            case DELETE -> Files.delete(log);
            case FIFO -> {
                Files.delete(log);
                if (new ProcessBuilder("mkfifo", log.toString()).inheritIO().start().waitFor() == 0) {
                    Thread.sleep(200);
                    Files.delete(log);
                }
            }
            case DIRECTORY -> {
                Files.delete(log);
                Files.createDirectory(log);
                Thread.sleep(200);
                Files.delete(log);
            }
        }
    }

    private static void truncate(Path log) throws IOException {
        try (FileChannel c = FileChannel.open(log, StandardOpenOption.WRITE)) {
            c.truncate(0);
        }
    }

    /**
     * Appends {@code text} at {@code speed} times the pace of its time stamps, in slices of 0.1 s of robot time (a
     * silence in the time stamps is a silence of the writer). With {@code renameTo}, halfway the log is renamed there
     * and an empty one created, and the rest still goes to the renamed file (the logger's handle); with {@code pause},
     * another program writes a line to the new file first and the logger pauses past the quiet time, so that watch
     * has turned to the new file when the rest comes.
     */
    static void write(Path log, String text, int speed, Path renameTo, boolean pause) throws Exception {
        String[] lines = text.split("(?<=\n)", -1);
        try (OutputStream out = Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND)) {
            StringBuilder slice = new StringBuilder();
            double sliceStart = 0;
            for (int i = 0; i < lines.length; i++) {
                String line = lines[i];
                double t = time(line);
                if (!Double.isNaN(t) && t - sliceStart >= 0.1) {
                    out.write(slice.toString().getBytes(StandardCharsets.UTF_8));
                    out.flush();
                    slice.setLength(0);
                    Thread.sleep(Math.round((t - sliceStart) * 1000 / speed));
                    sliceStart = t;
                }
                if (renameTo != null && i == lines.length / 2 && !Double.isNaN(t)) {
                    Files.move(log, renameTo);
                    Files.writeString(log, pause ? "yarprun: starting\n" : "");
                    renameTo = null;
                    if (pause) {
                        Thread.sleep(LogFollower.QUIET_MILLIS * 3 / 2);
                    }
                }
                slice.append(line);
            }
            out.write(slice.toString().getBytes(StandardCharsets.UTF_8));
        }
    }

    /** The time stamp of a record's first line, or NaN for another line. */
    static double time(String line) {
        int tab = line.indexOf('\t');
        if (tab <= 0 || !Character.isDigit(line.charAt(0))) {
            return Double.NaN;
        }
        try {
            return Double.parseDouble(line.substring(0, tab));
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
