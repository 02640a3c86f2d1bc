package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.Optional;

/** {@code --abstraction FILE}, shared by the commands that read logs: the one place the option is resolved. */
final class AbstractionOption {

    @Option(names = "--abstraction", paramLabel = "FILE",
            description = "Abstraction JSON (default: the embedded thesis Tables 4.1/4.2 with the Section 5.2 bands; "
                    + "commands that read models: the one the models were learned with).")
    Path file;

    /** The abstraction the option names, or the default when it is not given. */
    Abstraction load() throws AbstractionException {
        return file == null ? Abstraction.defaults() : Abstraction.load(file);
    }

    /**
     * For commands that read models: the abstraction the option names when it is given, else the one the models
     * were learned with ({@code stored}, their {@code abstraction.json}), else the default.
     */
    Abstraction loadFor(Optional<Path> stored) throws AbstractionException {
        if (file == null && stored.isPresent()) {
            return Abstraction.load(stored.get());
        }
        return load();
    }
}
