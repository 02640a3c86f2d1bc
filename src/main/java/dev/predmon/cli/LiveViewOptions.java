package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.live.Board;
import dev.predmon.live.HttpAddress;
import dev.predmon.live.LiveServer;
import dev.predmon.live.RobotNames;
import dev.predmon.model.ModelSet;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

import java.io.IOException;
import java.io.PrintWriter;
import java.time.Duration;
import java.util.List;

/**
 * {@code --http [HOST:]PORT}, {@code --stale-after S} and the robots' names ({@code --name}, {@code --name-pattern}):
 * the live view, for {@code watch} and {@code demo}.
 */
final class LiveViewOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    @Option(names = "--http", paramLabel = "[HOST:]PORT", converter = AddressConverter.class,
            description = "Also serve a live view at http://HOST:PORT/: a page with one tile per log, /events "
                    + "(Server-Sent Events) and /status (JSON). Loopback unless HOST is given; port 0 takes a free "
                    + "port. Read-only.")
    HttpAddress http;

    private double staleSeconds = 10;

    @Option(names = "--stale-after", paramLabel = "S", defaultValue = "10",
            description = "In the live view, a log that has not grown for S seconds is STALE, or its run ended when "
                    + "the tree had stopped every action it started (default: ${DEFAULT-VALUE}).")
    void staleAfter(double seconds) {
        if (!(seconds > 0) || Double.isInfinite(seconds)) {
            // a usage error of its own: picocli would name the setter method, not the option
            throw new ParameterException(mixee.commandLine(), "--stale-after must be a positive number of seconds, got "
                    + seconds);
        }
        staleSeconds = seconds;
    }

    @Option(names = "--name", paramLabel = "NAME",
            description = "In the live view, the robot's name on the log's tile (one log only; see --name-pattern).")
    String name;

    @Option(names = "--name-pattern", paramLabel = "PATTERN",
            description = "In the live view, name each log's robot from its path: {file} is the file's name without "
                    + ".log/.txt, {dir} the name of its directory (default: " + RobotNames.DEFAULT + "; '{dir}' names "
                    + "robots/r1/monitor.log r1).")
    String namePattern;

    /**
     * The live view's state for these models, or null without {@code --http}.
     *
     * @param several  whether several logs are (or may be) watched: {@code --name} names only one
     * @param watching what is watched, in words, for the page to say while no log is there yet
     */
    Board board(ModelSet models, Abstraction abstraction, boolean several, List<String> watching) {
        if (http == null) {
            if (name != null || namePattern != null) {
                throw new ParameterException(mixee.commandLine(), (name != null ? "--name" : "--name-pattern")
                        + " names robots in the live view: give --http too");
            }
            return null;
        }
        Board board = new Board(models, abstraction, Duration.ofMillis(Math.round(staleSeconds * 1000)), names(several));
        board.watching(watching);
        return board;
    }

    private RobotNames names(boolean several) {
        if (name != null && namePattern != null) {
            throw new ParameterException(mixee.commandLine(), "--name or --name-pattern, not both");
        }
        try {
            if (name != null) {
                if (several) {
                    throw new ParameterException(mixee.commandLine(), "--name names the robot of one log; with "
                            + "several, name them from their paths with --name-pattern (e.g. '{dir}')");
                }
                return RobotNames.fixed(name);
            }
            return namePattern == null ? RobotNames.byFile() : RobotNames.pattern(namePattern);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(mixee.commandLine(), (name != null ? "--name: " : "--name-pattern: ")
                    + e.getMessage());
        }
    }

    /**
     * Starts serving {@code board} (null: nothing to serve, returns null) and says where on {@code err}, with a
     * warning when other machines may reach it.
     */
    LiveServer start(PrintWriter err, Board board) throws BadInputException {
        if (board == null) {
            return null;
        }
        LiveServer server;
        try {
            server = LiveServer.start(http, board);
            if (!http.loopback()) {
                err.println("predmon: warning: the live view listens on " + http.host() + ":" + http.port()
                        + ", which other machines may reach; it is read-only and asks for no password");
            }
        } catch (IOException e) {
            throw new BadInputException("--http " + http.host() + ":" + http.port() + ": cannot listen there: "
                    + e.getMessage(), e);
        }
        err.println("predmon: live view on " + server.url());
        err.flush();
        return server;
    }

    static final class AddressConverter implements ITypeConverter<HttpAddress> {
        @Override
        public HttpAddress convert(String value) {
            try {
                return HttpAddress.parse(value);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }
}
