package dev.predmon.model;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.PropertyModel;
import dev.predmon.forecast.StateStats;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A command that reads models while {@code learn} replaces them gets one complete set, the old one or the new one:
 * never the index of one learn with the DOT files or the forecast of the other, and never "missing" for a file the
 * index lists. The two sets here are the shipped models (four machines) and the same without the direct scenario
 * (three machines), both written by {@link ModelStore#write}.
 */
class ConcurrentReadTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    /** The shipped models as learn writes them. */
    private static Written all;
    /** The same without the direct scenario, its machine and its forecast statistics. */
    private static Written withoutDirect;

    @TempDir
    Path tmp;

    /** What one learn writes. */
    private record Written(ModelIndex index, Map<String, String> dots, String abstraction, ForecastModel forecast) {

        void writeTo(Path dir) throws IOException, BadInputException {
            ModelStore.write(dir, index, dots, abstraction, forecast);
        }
    }

    @BeforeAll
    static void twoSets() throws Exception {
        Path shipped = Path.of("models");
        ModelSet set = ModelStore.read(shipped, A);
        Map<String, String> dots = new LinkedHashMap<>();
        for (ModelIndex.Scenario s : set.index().scenarios()) {
            for (ModelIndex.Model m : s.models()) {
                dots.put(m.file(), Files.readString(shipped.resolve(m.file())));
            }
        }
        String abstraction = Files.readString(shipped.resolve(ModelStore.ABSTRACTION));
        all = new Written(set.index(), dots, abstraction, set.forecast());

        ModelIndex i = set.index();
        List<ModelIndex.Scenario> scenarios = i.scenarios().stream().filter(s -> !s.name().equals("direct")).toList();
        Map<String, String> fewer = new LinkedHashMap<>(dots);
        fewer.remove("direct.dot");
        ForecastModel f = set.forecast();
        List<PropertyModel> properties = new ArrayList<>();
        for (PropertyModel p : f.properties()) {
            if (p instanceof PropertyModel.OfBound b) {
                properties.add(new PropertyModel.OfBound(b.id(), new BoundModel(b.model().side(),
                        withoutDirect(b.model().model()))));
            } else if (p instanceof PropertyModel.OfEvent e && e.model().forecasts()) {
                properties.add(new PropertyModel.OfEvent(e.id(), e.model().with(withoutDirect(e.model().model()))));
            } else {
                properties.add(p);
            }
        }
        ForecastModel forecast = ForecastModel.of(f.unit(), f.runs(), properties);
        withoutDirect = new Written(new ModelIndex(i.format(), i.abstraction(), i.alphabet(), scenarios), fewer,
                abstraction, forecast);
    }

    /** {@code m} without the statistics of the machine {@code direct}. */
    private static ForecastModel withoutDirect(ForecastModel m) {
        Map<String, Map<Integer, StateStats>> states = new TreeMap<>(m.states());
        states.remove("direct");
        return new ForecastModel(m.format(), m.unit(), m.limit(), m.runs(), m.violating(), m.lows(), m.threshold(),
                m.thresholdNote(), m.validated(), states, m.startInputs(), m.calibration(), m.scorecards())
                .withClauses(m.clauses());
    }

    /** Whether {@code set} is all of one of the two: its index, its machines and its forecast. */
    private static boolean whole(ModelSet set) {
        List<String> ids = set.models().stream().map(LearnedModel::id).toList();
        List<String> listed = new ArrayList<>();
        set.index().scenarios().forEach(s -> s.models().forEach(m -> listed.add(m.file().replace(".dot", ""))));
        boolean four = ids.size() == 4 && ids.contains("direct");
        boolean three = ids.size() == 3 && !ids.contains("direct");
        return (four || three) && ids.equals(listed) && Set.copyOf(ids).containsAll(set.forecast().states().keySet())
                && set.forecast().states().containsKey("direct") == four;
    }

    /**
     * The replacement lands exactly between reading the index and reading the DOT files: the read is done again
     * and gives the new set whole (it failed with "direct.dot: missing (listed in index.json)").
     */
    @Test
    void aLearnThatReplacesTheModelsAfterTheIndexWasRead() throws Exception {
        Path dir = tmp.resolve("models");
        all.writeTo(dir);
        AtomicInteger reads = new AtomicInteger();
        ModelSet set = readReplacedAfterTheIndex(dir, withoutDirect, reads);
        assertEquals(2, reads.get(), "read twice");
        assertTrue(whole(set));
        assertEquals(3, set.models().size(), "the new models");
    }

    /** The other way round: the index of three machines read, then the directory holds four. */
    @Test
    void aLearnThatAddsAMachineAfterTheIndexWasRead() throws Exception {
        Path dir = tmp.resolve("models");
        withoutDirect.writeTo(dir);
        ModelSet set = readReplacedAfterTheIndex(dir, all, new AtomicInteger());
        assertTrue(whole(set));
        assertEquals(4, set.models().size(), "the new models");
    }

    /** Reads {@code dir}, replacing it with {@code next} once the first read has its index; counts the reads. */
    private static ModelSet readReplacedAfterTheIndex(Path dir, Written next, AtomicInteger reads) throws Exception {
        return ModelStore.read(dir, A, step -> {
            if (step.equals("index") && reads.getAndIncrement() == 0) {
                try {
                    next.writeTo(dir);
                } catch (IOException | BadInputException e) {
                    throw new IllegalStateException(e);
                }
            }
        });
    }

    /**
     * Two readers read while a writer replaces the directory 30 times, alternating the two sets: every read gives
     * one of them whole.
     */
    @Test
    void readsWhileLearnReplacesTheModelsAgainAndAgain() throws Exception {
        Path dir = tmp.resolve("models");
        all.writeTo(dir);
        AtomicBoolean writing = new AtomicBoolean(true);
        ConcurrentLinkedQueue<String> failures = new ConcurrentLinkedQueue<>();
        AtomicInteger reads = new AtomicInteger();
        List<Thread> readers = new ArrayList<>();
        for (int r = 0; r < 2; r++) {
            Thread t = new Thread(() -> {
                while (writing.get()) {
                    try {
                        if (!whole(ModelStore.read(dir, A))) {
                            failures.add("a mixed set");
                        }
                    } catch (BadInputException | RuntimeException e) {
                        failures.add(String.valueOf(e.getMessage()));
                    }
                    reads.incrementAndGet();
                }
            });
            t.start();
            readers.add(t);
        }
        try {
            for (int n = 0; n < 30; n++) {
                (n % 2 == 0 ? withoutDirect : all).writeTo(dir);
                Thread.sleep(n % 3 * 5L);
            }
        } finally {
            writing.set(false);
            for (Thread t : readers) {
                t.join(30_000);
                assertFalse(t.isAlive());
            }
        }
        assertTrue(reads.get() >= 10, "read " + reads.get() + " times");
        assertEquals(List.of(), List.copyOf(failures), "of " + reads.get() + " reads");
    }
}
