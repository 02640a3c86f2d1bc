package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import picocli.CommandLine.Option;

import java.nio.file.Path;

/** {@code --models DIR}, shared by the commands that match logs against learned models. */
final class ModelOptions {

    @Option(names = "--models", paramLabel = "DIR", defaultValue = "models",
            description = "Model directory written by 'learn' (default: ${DEFAULT-VALUE}).")
    Path dir;

    ModelSet load(Abstraction abstraction) throws BadInputException {
        return ModelStore.read(dir, abstraction);
    }
}
