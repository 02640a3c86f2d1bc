package dev.predmon.model;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.pipeline.Traces;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ModelStoreTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();

    @TempDir
    Path tmp;

    private static List<LearnedScenario> learned() {
        MealyTrace run = MealyMapping.toTrace(Traces.compact(new Records().level(80).charging(false)
                .isAt("kitchen", false).goTo("kitchen").status("kitchen", 1).level(60).isAt("kitchen", true)
                .halt("kitchen").list(), ABSTRACTION), "direct-1.log");
        ScenarioSpec spec = new ScenarioSpec("direct", false, "reaches the kitchen", List.of(Path.of("direct-1.log")));
        return List.of(ScenarioLearner.learnSamples(spec, List.of(run), MealyAlphabet.inputs(ABSTRACTION)));
    }

    private void writeModels(Path dir) throws IOException, BadInputException {
        List<LearnedScenario> l = learned();
        ModelStore.write(dir, LearnedModels.index(l, ABSTRACTION), LearnedModels.dots(l, MealyAlphabet.inputs(ABSTRACTION)),
                ABSTRACTION.canonicalJson());
    }

    @Test
    void roundTripKeepsBehaviourAndAlphabet() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        ModelSet set = ModelStore.read(dir, ABSTRACTION);
        assertEquals(1, set.models().size());
        LearnedModel m = set.models().get(0);
        assertEquals("direct", m.id());
        MealyTrace run = LearnedModels.samples(learned().get(0)).get(0);
        assertEquals(run.outputs(), m.machine().computeOutput(run.inputs()));
        assertTrue(Files.readString(dir.resolve("direct.dot")).startsWith("digraph"));
        assertTrue(Files.readString(dir.resolve("index.json")).contains("\"fingerprint\""));
    }

    @Test
    void learningTwiceGivesByteIdenticalDot() throws Exception {
        writeModels(tmp.resolve("a"));
        writeModels(tmp.resolve("b"));
        assertEquals(Files.readString(tmp.resolve("a/direct.dot")), Files.readString(tmp.resolve("b/direct.dot")));
    }

    @Test
    void aFailedWriteLeavesThePreviousModelsIntact() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        String before = Files.readString(dir.resolve("direct.dot"));
        Map<String, String> bad = new LinkedHashMap<>();
        bad.put("ok.dot", "digraph g {}");
        bad.put("no/such/dir.dot", "x");
        List<LearnedScenario> l = learned();
        assertThrows(IOException.class, () -> ModelStore.write(dir, LearnedModels.index(l, ABSTRACTION), bad,
                ABSTRACTION.canonicalJson()));
        assertEquals(before, Files.readString(dir.resolve("direct.dot")));
        assertTrue(Files.notExists(dir.resolve("ok.dot")));
        ModelStore.read(dir, ABSTRACTION);
        try (var s = Files.list(tmp)) {
            assertEquals(List.of(dir), s.toList(), "no staging directory left behind");
        }
    }

    @Test
    void modelsSetAsideByAKilledLearnAreStillRead() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        Files.move(dir, tmp.resolve("models.old-999999999-1")); // killed between the two renames
        assertEquals(1, ModelStore.read(dir, ABSTRACTION).models().size());
    }

    /** Killed between the renames, with its staging directory left behind: read works, the next learn too. */
    @Test
    void afterAKillBetweenTheRenamesTheNextLearnSucceeds() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        Files.move(dir, tmp.resolve("models.old-999999999-2"));
        Path staging = Files.createDirectories(tmp.resolve("models.new-999999999-1"));
        Files.writeString(staging.resolve("direct.dot"), "digraph g {"); // half-written
        assertEquals(1, ModelStore.read(dir, ABSTRACTION).models().size());
        writeModels(dir);
        assertEquals(1, ModelStore.read(dir, ABSTRACTION).models().size());
        assertTrue(Files.isRegularFile(dir.resolve("index.json")));
        assertTrue(Files.notExists(tmp.resolve("models.old-999999999-2")), "cleaned up once the new models are in place");
    }

    /**
     * When the previous models are only set aside and the model directory cannot be written (here a dangling link
     * named like it), the learn is refused and those models stay readable.
     */
    @Test
    void modelsOnlySetAsideSurviveARefusedWrite() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        Files.move(dir, tmp.resolve("models.old-999999999-3"));
        Files.createSymbolicLink(dir, tmp.resolve("nowhere"));
        BadInputException e = assertThrows(BadInputException.class, () -> writeModels(dir));
        assertTrue(e.getMessage().contains("symbolic link"), e.getMessage());
        assertEquals(1, ModelStore.read(dir, ABSTRACTION).models().size(), "the previous models are still readable");
    }

    /** Staging directories of killed learns (their process is gone) are removed; a live learn's is kept. */
    @Test
    void stagingLeftByAKilledLearnIsRemovedByTheNextOne() throws Exception {
        Path dir = tmp.resolve("models");
        Path dead = Files.createDirectories(tmp.resolve("models.new-999999999-42")); // above any pid_max
        Files.writeString(dead.resolve("index.json"), "{");
        Path live = Files.createDirectories(tmp.resolve("models.new-" + ProcessHandle.current().pid() + "-7"));
        writeModels(dir);
        assertTrue(Files.notExists(dead), "abandoned staging removed");
        assertTrue(Files.isDirectory(live), "a running learn's staging kept");
        assertEquals(1, ModelStore.read(dir, ABSTRACTION).models().size());
    }

    @Test
    void missingDirectoryIsOneLineNamingIt() {
        BadInputException e = assertThrows(BadInputException.class, () -> ModelStore.read(tmp.resolve("nope"), ABSTRACTION));
        assertTrue(e.getMessage().contains("nope") && e.getMessage().contains("learn"), e.getMessage());
    }

    @Test
    void truncatedIndexNamesTheFileAndLine() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        String index = Files.readString(dir.resolve("index.json"));
        Files.writeString(dir.resolve("index.json"), index.substring(0, index.length() / 2));
        BadInputException e = assertThrows(BadInputException.class, () -> ModelStore.read(dir, ABSTRACTION));
        assertTrue(e.getMessage().startsWith(dir.resolve("index.json") + ":"), e.getMessage());
        assertTrue(!e.getMessage().contains("\n"), "one line");
    }

    @Test
    void aDotThatIsNotAMealyMachineIsNamed() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        Files.writeString(dir.resolve("direct.dot"), "digraph g { s0 -> s1 [label=\"a\"]; }");
        BadInputException e = assertThrows(BadInputException.class, () -> ModelStore.read(dir, ABSTRACTION));
        assertTrue(e.getMessage().contains("direct.dot"), e.getMessage());
    }

    @Test
    void aModelWithInputsOutsideTheAbstractionIsRejected() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        Files.writeString(dir.resolve("direct.dot"), "digraph g {\n s0 [shape=\"circle\" label=\"0\"];\n"
                + " s0 -> s0 [label=\"teleport_i / OK\"];\n __start0 [label=\"\" shape=\"none\"];\n __start0 -> s0;\n}\n");
        BadInputException e = assertThrows(BadInputException.class, () -> ModelStore.read(dir, ABSTRACTION));
        assertTrue(e.getMessage().contains("teleport_i") && e.getMessage().contains("direct.dot"), e.getMessage());
    }

    @Test
    void modelsLearnedWithAnotherAbstractionAreRefused() throws Exception {
        Path dir = tmp.resolve("models");
        writeModels(dir);
        String json = new String(Abstraction.class.getResourceAsStream("default-abstraction.json").readAllBytes(),
                StandardCharsets.UTF_8)
                .replace("\"charging_station\"", "\"dock\"");
        Abstraction other = AbstractionFiles.fromJson("other.json", json);
        BadInputException e = assertThrows(BadInputException.class, () -> ModelStore.read(dir, other));
        assertTrue(e.getMessage().contains("abstraction"), e.getMessage());
    }
}
