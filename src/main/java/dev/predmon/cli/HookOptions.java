package dev.predmon.cli;

import dev.predmon.hooks.CommandHooks;
import dev.predmon.property.Property;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.List;

/** {@code --on-warning CMD}, {@code --on-violation CMD}, {@code --on-recovered CMD} and their timeout: the warning delivered to the robot. */
final class HookOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    @Option(names = "--on-warning", paramLabel = "CMD",
            description = "Run CMD with /bin/sh -c for each warning: the event's JSON on its standard input, its main "
                    + "fields in PREDMON_* environment variables (see docs/watch.md). Only for what happens after "
                    + "watch started: warnings in what the logs already held go to the verdict and the page, not to "
                    + "CMD (with --no-follow the whole file counts). Never blocks the monitor; a failing or slow "
                    + "command is reported on stderr and not run again.")
    String onWarning;

    @Option(names = "--on-violation", paramLabel = "CMD",
            description = "Run CMD for each violation of the property, as --on-warning does for each warning.")
    String onViolation;

    @Option(names = "--on-recovered", paramLabel = "CMD",
            description = "Run CMD for each recovery (a warning's or a violation's cause ended; PREDMON_PROPERTY names "
                    + "the property), as --on-warning does for each warning: an alarm raised by the other hooks ends "
                    + "when its cause does.")
    String onRecovered;

    private double timeoutSeconds = 10;

    @Option(names = "--hook-timeout", paramLabel = "S", defaultValue = "10",
            description = "Kill a hook command still running after S seconds (default: ${DEFAULT-VALUE}).")
    void timeout(double seconds) {
        if (!(seconds > 0) || seconds > 86_400) {
            // a usage error of its own: picocli would name the setter method, not the option
            throw new ParameterException(mixee.commandLine(), "--hook-timeout must be a number of seconds above 0 "
                    + "and at most 86400, got " + seconds);
        }
        timeoutSeconds = seconds;
    }

    private double holdSeconds = 5;

    @Option(names = "--hook-hold", paramLabel = "S", defaultValue = "5",
            description = "Run --on-recovered only once the alarm has stayed over for S seconds; a warning or "
                    + "violation of the same property raised again before then runs no command (the robot's alarm "
                    + "is still up), unless it is a violation after a warning, so that a reading flapping at the "
                    + "bound runs a few commands, not three at every crossing. 0 runs every command at once "
                    + "(default: ${DEFAULT-VALUE}).")
    void hold(double seconds) {
        if (!(seconds >= 0) || seconds > 86_400) {
            throw new ParameterException(mixee.commandLine(), "--hook-hold must be a number of seconds from 0 to "
                    + "86400, got " + seconds);
        }
        holdSeconds = seconds;
    }

    /**
     * The hooks, reporting on {@code err}; null when neither command is given.
     *
     * @param bound the property's bound, below which it is violated (NaN when there is none): values below it are
     *              rounded down in the hooks' environment, as on the page
     * @param properties every property of the abstraction, whose words the hooks' environment gives
     */
    CommandHooks open(PrintWriter err, double bound, List<Property> properties) {
        if (onWarning == null && onViolation == null && onRecovered == null) {
            return null;
        }
        return new CommandHooks(onWarning, onViolation, onRecovered, Duration.ofMillis(Math.round(timeoutSeconds * 1000)),
                Duration.ofMillis(Math.round(holdSeconds * 1000)), bound, line -> {
            err.println("predmon: " + line);
            err.flush();
        }).describing(properties);
    }
}
