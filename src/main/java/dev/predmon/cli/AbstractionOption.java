package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import picocli.CommandLine.Option;

import java.nio.file.Path;

/** {@code --abstraction FILE}, shared by the commands that read logs. */
final class AbstractionOption {

    @Option(names = "--abstraction", paramLabel = "FILE",
            description = "Abstraction JSON (default: the embedded thesis Tables 4.1/4.2 with the Section 5.2 bands).")
    Path file;

    Abstraction load() throws AbstractionException {
        return file == null ? Abstraction.defaults() : Abstraction.load(file);
    }
}
