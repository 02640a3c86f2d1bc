package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.files.OutputFiles;
import picocli.CommandLine.Option;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/** {@code --abstraction NAME|FILE}, shared by the commands that read logs: the one place the option is resolved. */
final class AbstractionOption {

    @Option(names = "--abstraction", paramLabel = "NAME|FILE",
            description = "A built-in abstraction by name (thesis: the thesis's Tables 4.1/4.2 with the Section 5.2 "
                    + "bands, the default; scope-fetch: the R1 fetch-and-carry tree of the SCOPE recordings; nav2: a "
                    + "robot on ROS 2 navigation, for rosbag2 recordings), or an "
                    + "abstraction JSON file ('predmon abstraction show NAME' prints one to start from). Commands "
                    + "that read models default to the one the models were learned with.")
    String value;

    /** The option as an input of the command, when it names a file: outputs must not replace it. */
    List<OutputFiles.Input> inputs() {
        return value != null && Files.exists(Path.of(value))
                ? List.of(new OutputFiles.Input(Path.of(value), "--abstraction")) : List.of();
    }

    /** The abstraction the option names, or the default when it is not given. */
    Abstraction load() throws AbstractionException {
        return resolve(value);
    }

    /**
     * For commands that read models: the abstraction the option names when it is given, else the one the models
     * were learned with ({@code stored}, their {@code abstraction.json}), else the default.
     */
    Abstraction loadFor(Optional<Path> stored) throws AbstractionException {
        if (value == null && stored.isPresent()) {
            return AbstractionFiles.load(stored.get());
        }
        return load();
    }

    /**
     * The abstraction a value names: an existing file is read as one; otherwise a built-in name; {@code null} is the
     * default, {@code thesis}.
     */
    static Abstraction resolve(String value) throws AbstractionException {
        if (value == null) {
            return AbstractionFiles.defaults();
        }
        Path file = Path.of(value);
        if (Files.exists(file) || AbstractionFiles.builtin(value).isEmpty()) {
            if (!Files.exists(file)) {
                throw new AbstractionException(value + ": cannot read: no such file (nor a built-in abstraction: "
                        + String.join(", ", AbstractionFiles.BUILTIN_NAMES) + ")");
            }
            return AbstractionFiles.load(file);
        }
        return AbstractionFiles.builtin(value).orElseThrow();
    }
}
