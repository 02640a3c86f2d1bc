package dev.predmon.cli;

import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The shipped sample-logs/ and models/, and the demo a newcomer runs first. */
class DemoAndShippedDataTest {

    private static final Path SAMPLES = Path.of("sample-logs");
    private static final Path MODELS = Path.of("models");

    /**
     * The learn command of scripts/regenerate-samples.sh, the documented way to remake models/ from sample-logs/:
     * its arguments after {@code learn}.
     */
    static List<String> regenerateLearnArguments() throws IOException {
        String prefix = "java -jar \"$JAR\" learn ";
        List<String> learn = Files.readAllLines(Path.of("scripts", "regenerate-samples.sh")).stream()
                .map(String::strip).filter(l -> l.startsWith(prefix)).toList();
        assertEquals(1, learn.size(), "one learn command in scripts/regenerate-samples.sh: " + learn);
        return List.of(learn.get(0).substring(prefix.length()).strip().split(" +"));
    }

    /**
     * The regenerate script's learn command, run on the shipped samples, gives the shipped model directory byte for
     * byte: every file, forecast.json and index.json included, and no other. A user who relearns the samples gets the
     * models the demo and the documentation show; else run scripts/regenerate-samples.sh.
     */
    @Test
    void shippedModelsAreWhatTheRegenerateScriptLearns(@TempDir Path tmp) throws IOException {
        List<String> args = regenerateLearnArguments();
        assertEquals(List.of("--logs", SAMPLES.toString(), "--models", MODELS.toString()), args,
                "the script learns the shipped samples into the shipped models");
        Path relearned = tmp.resolve("models");
        Cli r = Cli.run("learn", "--logs", SAMPLES.toString(), "--models", relearned.toString());
        assertEquals(0, r.code(), r.err());
        List<String> shipped = files(MODELS);
        assertTrue(shipped.containsAll(List.of("forecast.json", "index.json", "abstraction.json")), shipped.toString());
        assertEquals(shipped, files(relearned), "the set of model files");
        // index.json too: it holds nothing that varies from run to run (no learning time), so running learn in a
        // checkout leaves the committed models as they are
        for (String name : shipped) {
            assertEquals(Files.readString(MODELS.resolve(name)), Files.readString(relearned.resolve(name)),
                    "models/" + name + " is not what learn writes for sample-logs/: run scripts/regenerate-samples.sh");
        }
    }

    /**
     * The models carry the abstraction they were learned with: its fingerprint (without the properties' actions, which
     * are advice, and the properties other than the forecast's, which label no run) is the index's.
     */
    @Test
    void shippedModelsCarryTheirAbstraction() throws Exception {
        String fingerprint = AbstractionFiles.load(MODELS.resolve("abstraction.json")).fingerprint();
        assertTrue(Files.readString(MODELS.resolve("index.json")).contains("\"fingerprint\" : \"" + fingerprint + "\""));
        assertEquals(AbstractionFiles.defaults().fingerprint(), fingerprint);
    }

    private static List<String> files(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void demoShowsTheWarningBeforeTheViolationThenAQuietNominalRun(@TempDir Path tmp) {
        Cli r = Cli.run("demo", "--seconds", "1.5", "--work", tmp.toString());
        assertEquals(0, r.code(), r.out() + r.err());
        String out = r.out();
        int warning = out.indexOf("WARNING");
        int violation = out.indexOf("VIOLATION");
        assertTrue(warning > 0 && violation > warning, out);
        assertTrue(out.matches("(?s).*predicted [0-9.]+ s ahead: warning at battery [0-9.]+%, violation at [0-9.]+%.*"),
                out);
        assertTrue(out.contains("run ended with no warning and no violation"), out);
    }

    @Test
    void demoLearnsModelsFirstWhenThereAreNone(@TempDir Path tmp) {
        Path models = tmp.resolve("fresh-models");
        Cli r = Cli.run("demo", "--seconds", "1", "--work", tmp.toString(), "--models", models.toString());
        assertEquals(0, r.code(), r.out() + r.err());
        assertTrue(r.out().contains("learning them from"), r.out());
        assertTrue(Files.isRegularFile(models.resolve("index.json")));
    }
}
