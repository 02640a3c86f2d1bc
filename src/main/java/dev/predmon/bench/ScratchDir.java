package dev.predmon.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;

/** A directory of a bench's own files, deleted with everything in it when closed. */
final class ScratchDir implements AutoCloseable {

    private final Path path;

    /** A new directory under {@code parent}, its name starting with {@code prefix}. */
    ScratchDir(Path parent, String prefix) throws IOException {
        this.path = Files.createTempDirectory(parent, prefix);
    }

    Path path() {
        return path;
    }

    /** {@code name} in this directory. */
    Path resolve(String name) {
        return path.resolve(name);
    }

    @Override
    public void close() throws IOException {
        try (Stream<Path> files = Files.walk(path)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
