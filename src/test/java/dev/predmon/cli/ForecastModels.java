package dev.predmon.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * Models with a forecast, for the tests of what the forecast shows: the shipped ones when they carry it, else learned
 * from the shipped sample logs once per test JVM (learning takes seconds) and deleted when the JVM exits.
 */
final class ForecastModels {

    private static Path dir;

    private ForecastModels() {
    }

    static synchronized Path get() {
        if (dir == null && Files.isRegularFile(Path.of("models", "forecast.json"))) {
            dir = Path.of("models");
        }
        if (dir == null) {
            try {
                Path tmp = Files.createTempDirectory("predmon-forecast-models-");
                Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(tmp)));
                Path models = tmp.resolve("models");
                Cli r = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
                assertEquals(0, r.code(), r.err());
                dir = models;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return dir;
    }

    private static void delete(Path tree) {
        try (Stream<Path> files = Files.walk(tree)) {
            for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(f);
            }
        } catch (IOException e) {
            // a temporary directory is left behind
        }
    }
}
