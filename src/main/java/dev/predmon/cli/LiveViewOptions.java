package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.live.Board;
import dev.predmon.live.HttpAddress;
import dev.predmon.live.LiveServer;
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

/** {@code --http [HOST:]PORT} and {@code --stale-after S}: the live view, for {@code watch} and {@code demo}. */
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
            description = "In the live view, mark a log STALE when it has not grown for S seconds (default: "
                    + "${DEFAULT-VALUE}).")
    void staleAfter(double seconds) {
        if (!(seconds > 0) || Double.isInfinite(seconds)) {
            // a usage error of its own: picocli would name the setter method, not the option
            throw new ParameterException(mixee.commandLine(), "--stale-after must be a positive number of seconds, got "
                    + seconds);
        }
        staleSeconds = seconds;
    }

    /** The live view's state for these models, or null without {@code --http}. */
    Board board(ModelSet models, Abstraction abstraction) {
        return http == null ? null : new Board(models, abstraction, Duration.ofMillis(Math.round(staleSeconds * 1000)));
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
