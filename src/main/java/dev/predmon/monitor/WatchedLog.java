package dev.predmon.monitor;

import dev.predmon.parse.LogFormat;

import java.nio.file.Path;

/**
 * One log of a {@link Fleet}: its own {@link PredictiveMonitor} (models' states, runs, warning) and its own
 * {@link LogWatcher}, so that logs never influence each other.
 */
public final class WatchedLog {

    private final String name;
    private final Path path;
    private final PredictiveMonitor monitor;
    private final LogWatcher watcher;
    /** Whether it is a file, read in the abstraction's format (not a live robot's connection, named by a path). */
    private final boolean file;
    /** Files its watcher held open after its last poll, as {@link OpenFiles} counted them. */
    int openFiles;
    /** When it last had something new, as a stamp of its fleet's {@link OpenFiles}: higher is later. */
    long active;
    /** Whether the last {@link Wakeups#due} gave it only because it was written ({@link Wakeups#onlyWritten}). */
    boolean onlyWritten;
    /** What the user was last told about it (something not a file at its path, a read that failed), or null. */
    String told;

    WatchedLog(Path path, String name, LogFormat format, Fleet.Settings settings, FleetListener listener) {
        this.path = path;
        this.name = name;
        this.file = format == null;
        this.monitor = new PredictiveMonitor(settings.models(), settings.abstraction(), settings.tolerance(),
                settings.confirm(), settings.rule(), e -> listener.event(this, e));
        this.watcher = LogWatcher.withRelease(path, monitor, p -> listener.problem(this, p),
                r -> listener.record(this, r), settings.release(), format);
    }

    /** The log as named on the command line or found under a directory or glob; events are tagged with it. */
    public String name() {
        return name;
    }

    public Path path() {
        return path;
    }

    public PredictiveMonitor monitor() {
        return monitor;
    }

    public LogWatcher watcher() {
        return watcher;
    }

    /** Whether it is a file at its path (a live robot's connection is not), which may be deleted. */
    boolean file() {
        return file;
    }

    @Override
    public String toString() {
        return name;
    }
}
