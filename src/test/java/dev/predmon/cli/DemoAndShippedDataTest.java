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
     * Relearning the shipped samples must give the shipped model directory byte for byte, index included; else run
     * scripts/regenerate-samples.sh.
     */
    @Test
    void shippedModelsAreNotStale(@TempDir Path tmp) throws IOException {
        Path relearned = tmp.resolve("models");
        Cli r = Cli.run("learn", "--logs", SAMPLES.toString(), "--models", relearned.toString());
        assertEquals(0, r.code(), r.err());
        List<String> shipped = dots(MODELS);
        assertEquals(shipped, dots(relearned), "the set of model files");
        for (String dot : shipped) {
            assertEquals(Files.readString(MODELS.resolve(dot)), Files.readString(relearned.resolve(dot)),
                    dot + " is stale: run scripts/regenerate-samples.sh");
        }
        assertEquals(Files.readString(relearned.resolve("abstraction.json")), Files.readString(MODELS.resolve("abstraction.json")),
                "abstraction.json is stale: run scripts/regenerate-samples.sh");
        // index.json too, byte for byte: it holds nothing that varies from run to run (no learning time), so
        // running learn in a checkout leaves the committed models as they are
        assertEquals(Files.readString(MODELS.resolve("index.json")), Files.readString(relearned.resolve("index.json")),
                "index.json differs from what learn writes for the same logs");
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

    private static List<String> dots(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".dot")).sorted().toList();
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
