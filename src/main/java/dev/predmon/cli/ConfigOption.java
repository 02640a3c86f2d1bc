package dev.predmon.cli;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.nio.file.Path;

/**
 * {@code --config FILE}: the command's settings from one file ({@link ConfigFile}), so that a service has one file to
 * edit. Options on the command line override the file.
 */
final class ConfigOption {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    private ConfigFile file;

    @Option(names = "--config", paramLabel = "FILE",
            description = "Read the settings from FILE, one 'name = value' a line: the long option's name without "
                    + "its dashes (log = robots/, http = 8080, on-warning = ...), the value as on the command line "
                    + "without quotes, true or false for a switch; '#' starts a comment. log may be repeated. Options "
                    + "on the command line override the file.")
    void read(Path path) {
        // Picocli applies default values after the command line's own, so the file is read before it asks for them.
        file = ConfigFile.read(path, mixee);
        mixee.defaultValueProvider(file);
    }

    /** After parsing: options set several times in the file get every value (picocli's defaults hold one). */
    void complete() {
        if (file != null) {
            file.complete(mixee);
        }
    }
}
