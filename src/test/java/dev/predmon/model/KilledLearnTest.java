package dev.predmon.model;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.Learning;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code kill -9} of a real {@code predmon learn} process at many points in time: afterwards the model directory
 * always loads, and what loads is exactly the previous model set or exactly the new one, never a mixture.
 * Most kill points are timed from the child's report of its last scenario, right before it writes the models;
 * {@link ModelStoreTest} covers the states between the renames deterministically.
 */
class KilledLearnTest {

    private static final Path SAMPLE_LOGS = Path.of("sample-logs");

    @TempDir
    Path tmp;

    @Test
    @Timeout(120)
    void aLearnKilledAtAnyMomentLeavesPreviousOrNewModels() throws Exception {
        Abstraction abstraction = Abstraction.defaults();
        Path logs = tmp.resolve("logs"); // three runs per scenario: a learn of about a second
        try (Stream<Path> scenarios = Files.list(SAMPLE_LOGS)) {
            for (Path scenario : scenarios.filter(Files::isDirectory).toList()) {
                copyTree(scenario, logs.resolve(scenario.getFileName()), 3);
            }
        }
        Path newRef = tmp.resolve("new-ref");
        Learning.learnAndWrite(logs, newRef, abstraction, l -> { });
        Map<String, String> newModels = files(newRef);

        // The previous models differ from the new ones: learned from one scenario only.
        Path oneScenario = tmp.resolve("one-scenario");
        copyTree(logs.resolve("direct"), oneScenario.resolve("direct"), 1);
        Path models = tmp.resolve("models");
        Learning.learnAndWrite(oneScenario, models, abstraction, l -> { });
        Map<String, String> previousModels = files(models);
        assertNotEquals(previousModels, newModels);

        // learn prints each scenario once learned and writes the models after the last one (recharge):
        // kills timed from that line land in ModelStore.write, the others while parsing and learning.
        List<Kill> kills = List.of(new Kill(null, 150), new Kill("scenario direct", 0), new Kill("scenario recharge", 0),
                new Kill("scenario recharge", 15), new Kill("scenario recharge", 30), new Kill("scenario recharge", 45),
                new Kill("scenario recharge", 55), new Kill("scenario recharge", 70));
        List<String> outcomes = new ArrayList<>();
        for (Kill kill : kills) {
            Process p = learn(logs, models);
            kill.await(p);
            boolean finished = !p.isAlive();
            p.destroyForcibly().waitFor();
            ModelSet set = ModelStore.read(models, abstraction);
            Map<String, String> loaded = files(set.dir());
            boolean isNew = loaded.equals(newModels);
            assertTrue(isNew || loaded.equals(previousModels),
                    kill + ": " + set.dir() + " holds neither the previous nor the new model set: " + loaded.keySet());
            assertEquals(set.index().scenarios().stream().mapToInt(s -> s.models().size()).sum(), set.models().size());
            outcomes.add(kill + (finished ? " finished" : " killed") + " -> " + (isNew ? "new" : "previous")
                    + (set.dir().endsWith("models.old") ? " (from models.old)" : ""));
            if (isNew) {
                // start again from the previous models, so that the next kill can tell them apart
                Learning.learnAndWrite(oneScenario, models, abstraction, l -> { });
            }
        }
        Process last = learn(logs, models);
        assertEquals(0, last.waitFor(), "an undisturbed learn after all the kills succeeds");
        assertEquals(newModels, files(ModelStore.read(models, abstraction).dir()));
        try (Stream<Path> s = Files.list(tmp)) {
            assertEquals(List.of(), s.filter(p -> p.getFileName().toString().startsWith("models.new-")).toList(),
                    "no staging directory of a killed learn is left once a learn succeeds");
        }
        System.out.println("KilledLearnTest: " + outcomes);
    }

    /** When to kill: {@code millis} after the child printed a line starting with {@code after} (or after start). */
    private record Kill(String after, long millis) {

        void await(Process p) throws Exception {
            if (after != null) {
                BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
                String line;
                while ((line = out.readLine()) != null && !line.startsWith(after)) {
                    // the lines before the one that times the kill
                }
            }
            p.waitFor(millis, TimeUnit.MILLISECONDS);
        }

        @Override
        public String toString() {
            return millis + " ms after " + (after == null ? "start" : "'" + after + "'");
        }
    }

    /** Starts {@code predmon learn} as a separate JVM. */
    private static Process learn(Path logs, Path models) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // C1 only: the child starts in a third of the time, and what is tested is where it dies, not its speed
        return new ProcessBuilder(java, "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "dev.predmon.cli.Main",
                "learn", "--logs", logs.toString(), "--models", models.toString())
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start();
    }

    /** File name to content of a model directory, without the learning times that differ from run to run. */
    private static Map<String, String> files(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.toList()) {
                m.put(p.getFileName().toString(),
                        Files.readString(p).replaceAll("\"learningMillis\" : \\d+", "\"learningMillis\" : _"));
            }
        }
        return m;
    }

    /** Copies scenario.json and the first {@code logs} logs of a scenario directory. */
    private static void copyTree(Path from, Path to, int logs) throws IOException {
        Files.createDirectories(to);
        Files.copy(from.resolve("scenario.json"), to.resolve("scenario.json"));
        try (Stream<Path> s = Files.list(from)) {
            for (Path p : s.filter(p -> p.toString().endsWith(".log")).sorted().limit(logs).toList()) {
                Files.copy(p, to.resolve(p.getFileName()));
            }
        }
    }
}
