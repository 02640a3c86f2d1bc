package dev.predmon.monitor;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** A watched directory: its logs by file name, and whether a new file in it may be a new log. */
final class WatchedDirectory {
    final Path dir;
    final DirectoryWatch.Key key;
    final Object identity;
    final Map<Path, List<WatchedLog>> logs = new HashMap<>();
    final Set<WatchedLog> orphans = new LinkedHashSet<>();
    boolean source;

    WatchedDirectory(Path dir, DirectoryWatch.Key key) {
        this.dir = dir;
        this.key = key;
        this.identity = DirectoryWatch.identity(dir);
    }
}
