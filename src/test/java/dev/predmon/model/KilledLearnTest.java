package dev.predmon.model;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
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
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code kill -9} of a real learn process: afterwards the model directory always loads, what loads is exactly the
 * previous model set or exactly the new one, never a mixture, the next learn succeeds and leaves nothing behind,
 * and the user's files next to the model directory are untouched. One test kills a {@link PausedLearn} just
 * before each step of writing the models (every rename included); the other kills {@code predmon learn} at
 * moments timed from its output.
 */
class KilledLearnTest {

    private static final Path SAMPLE_LOGS = Path.of("sample-logs");

    @TempDir
    Path tmp;

    private Path logs;
    private Path oneScenario;
    private Map<String, String> newModels;
    private Map<String, String> previousModels;

    /** Logs of three runs per scenario (a learn of about a second), the models they give, and different previous ones. */
    private void prepare(Path models) throws Exception {
        Abstraction abstraction = AbstractionFiles.defaults();
        logs = tmp.resolve("logs");
        try (Stream<Path> scenarios = Files.list(SAMPLE_LOGS)) {
            for (Path scenario : scenarios.filter(Files::isDirectory).toList()) {
                copyTree(scenario, logs.resolve(scenario.getFileName()), 3);
            }
        }
        Path newRef = tmp.resolve("reference/new");
        Learning.learnAndWrite(logs, newRef, abstraction, l -> { });
        newModels = files(newRef);
        // The previous models differ from the new ones: learned from one scenario only.
        oneScenario = tmp.resolve("one-scenario");
        copyTree(logs.resolve("direct"), oneScenario.resolve("direct"), 1);
        Learning.learnAndWrite(oneScenario, models, abstraction, l -> { });
        previousModels = files(models);
        assertNotEquals(previousModels, newModels);
    }

    /** A user's files next to the model directory, named like what learn makes: learn must never touch them. */
    private static Map<String, String> userFilesBeside(Path models) throws IOException {
        Path parent = models.getParent();
        Files.writeString(parent.resolve("thesis.tex"), "\\chapter{Results}\n");
        Path backup = Files.createDirectories(parent.resolve(models.getFileName() + ".old"));
        Files.writeString(backup.resolve("index.json"), "my own backup\n");
        Path other = Files.createDirectories(parent.resolve(models.getFileName() + ".new-2024-backup"));
        Files.writeString(other.resolve("notes.txt"), "keep\n");
        return userFiles(parent, models);
    }

    private static Map<String, String> userFiles(Path parent, Path models) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.walk(parent)) {
            for (Path p : s.filter(Files::isRegularFile).toList()) {
                String rel = parent.relativize(p).toString();
                if (!rel.startsWith(models.getFileName() + "/") && !rel.matches(models.getFileName() + "\\.(new|old)-\\d+-\\d+/.*")) {
                    m.put(rel, Files.readString(p));
                }
            }
        }
        return m;
    }

    /** The directories learn left beside the models (staging, set aside), by name. */
    private static List<String> leftovers(Path models) throws IOException {
        try (Stream<Path> s = Files.list(models.getParent())) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.matches(models.getFileName() + "\\.(new|old)-\\d+-\\d+"))
                    .sorted().toList();
        }
    }

    @Test
    @Timeout(120)
    void aLearnKilledJustBeforeEachStepLeavesPreviousOrNewModelsAndTheNextLearnCleansUp() throws Exception {
        Abstraction abstraction = AbstractionFiles.defaults();
        Path models = tmp.resolve("workspace/models");
        prepare(models);
        Map<String, String> user = userFilesBeside(models);
        // before the set-aside rename the previous models are in place; after the move-in, the new ones
        Map<String, Boolean> expectNew = new LinkedHashMap<>();
        expectNew.put("write", false);
        expectNew.put("set-aside", false);
        expectNew.put("move-in", false);
        expectNew.put("clean-up", true);
        for (Map.Entry<String, Boolean> step : expectNew.entrySet()) {
            Process p = pausedLearn(logs, models, step.getKey());
            String said = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8)).readLine();
            assertEquals("paused before " + step.getKey(), said);
            p.destroyForcibly().waitFor();

            ModelSet set = ModelStore.read(models, abstraction);
            assertEquals(step.getValue() ? newModels : previousModels, files(set.dir()),
                    "killed before " + step.getKey() + ", read from " + set.dir());
            assertEquals(user, userFiles(models.getParent(), models), "killed before " + step.getKey());

            Learning.learnAndWrite(oneScenario, models, abstraction, l -> { }); // the next learn, back to previous
            assertEquals(previousModels, files(ModelStore.read(models, abstraction).dir()));
            assertEquals(List.of(), leftovers(models), "the next learn after a kill before " + step.getKey());
            assertEquals(user, userFiles(models.getParent(), models), "the next learn after a kill before " + step.getKey());
        }
    }

    @Test
    @Timeout(120)
    void aLearnKilledAtAnyMomentLeavesPreviousOrNewModels() throws Exception {
        Abstraction abstraction = AbstractionFiles.defaults();
        Path models = tmp.resolve("models");
        prepare(models);

        // learn prints each scenario once learned and writes the models after the last one (recharge):
        // kills timed from that line land in ModelStore.write, the others while parsing and learning.
        List<Kill> kills = List.of(new Kill(null, 150), new Kill("scenario direct", 0), new Kill("scenario recharge", 0),
                new Kill("scenario recharge", 15), new Kill("scenario recharge", 30), new Kill("scenario recharge", 45),
                new Kill("scenario recharge", 55), new Kill("scenario recharge", 70));
        for (Kill kill : kills) {
            Process p = learn(logs, models);
            kill.await(p);
            p.destroyForcibly().waitFor();
            ModelSet set = ModelStore.read(models, abstraction);
            Map<String, String> loaded = files(set.dir());
            boolean isNew = loaded.equals(newModels);
            assertTrue(isNew || loaded.equals(previousModels),
                    kill + ": " + set.dir() + " holds neither the previous nor the new model set: " + loaded.keySet());
            assertEquals(set.index().scenarios().stream().mapToInt(s -> s.models().size()).sum(), set.models().size());
            if (isNew) {
                // start again from the previous models, so that the next kill can tell them apart
                Learning.learnAndWrite(oneScenario, models, abstraction, l -> { });
            }
        }
        Process last = learn(logs, models);
        assertEquals(0, last.waitFor(), "an undisturbed learn after all the kills succeeds");
        assertEquals(newModels, files(ModelStore.read(models, abstraction).dir()));
        assertEquals(List.of(), leftovers(models), "no staging directory of a killed learn is left once a learn succeeds");
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

    /** Starts a {@link PausedLearn} as a separate JVM. */
    private static Process pausedLearn(Path logs, Path models, String step) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return new ProcessBuilder(java, "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"),
                PausedLearn.class.getName(), logs.toString(), models.toString(), step)
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start();
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

    /** File name to content of a model directory (learn writes the same bytes for the same logs). */
    private static Map<String, String> files(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.toList()) {
                m.put(p.getFileName().toString(), Files.readString(p));
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
