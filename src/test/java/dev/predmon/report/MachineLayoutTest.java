package dev.predmon.report;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.evaluate.Evaluator;
import dev.predmon.evaluate.Progress;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.support.RealLogs;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The drawn machines as laid out: on every shipped model, folded and in full, no text overlaps another or a
 * state, every transition's label is written exactly once (a state's self-loops counted on one line), and the
 * caption's counts hold. The same on a random
 * 60-state machine, the size issue 12 asks to stay readable.
 */
class MachineLayoutTest {

    static Stream<LearnedModel> shipped() throws Exception {
        return ModelStore.read(Path.of("models"), AbstractionFiles.defaults()).models().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("shipped")
    void everyShippedModelIsDrawnWithoutOverlapsFoldedAndInFull(LearnedModel m) {
        for (MachineGraph g : List.of(MachineGraph.folded(m), MachineGraph.full(m))) {
            MachineLayout l = MachineLayout.of(g);
            assertEquals(List.of(), l.overlaps(), m.id() + (g.fold() ? " folded" : " full"));
            assertEquals(g.nodes().size(), l.states().size());
            List<String> labels = l.texts().stream().filter(MachineLayout.Text::label).map(MachineLayout.Text::text).toList();
            assertEquals(g.edges().stream().flatMap(e -> e.drawn().stream()).toList(), labels);
            for (MachineGraph.Edge e : g.edges()) {
                // One line per state for its self-loops, however many: the report lists them under the drawing.
                assertTrue(e.source() != e.target() || e.drawn().size() == 1, e.toString());
            }
            assertInside(l);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("shipped")
    void theFullDrawingHasEveryStateAndTransitionAndTheFoldedOneSaysWhatItLeftOut(LearnedModel m) {
        MachineGraph full = MachineGraph.full(m);
        MachineGraph folded = MachineGraph.folded(m);
        int transitions = 0;
        for (Integer s : m.machine().getStates()) {
            for (String in : m.machine().getInputAlphabet()) {
                transitions += m.machine().getSuccessor(s, in) != null ? 1 : 0;
            }
        }
        assertEquals(m.machine().size(), full.nodes().size());
        assertEquals(0, full.hidden());
        assertEquals(transitions, full.edges().stream().mapToInt(e -> e.labels().size()).sum());
        // Each folded state merges its query's and its reply's transitions into one label.
        assertEquals(transitions - folded.hidden(), folded.edges().stream().mapToInt(e -> e.labels().size()).sum());
        assertEquals(m.machine().size(), folded.nodes().size() + folded.hidden());
        assertTrue(ModelSection.caption(folded).startsWith(m.machine().size() + " states, " + folded.nodes().size()
                + " drawn: the other " + folded.hidden() + " only wait"), ModelSection.caption(folded));
    }

    @Test
    void depletedIsTwoStatesFoldedAndEighteenInFull() throws Exception {
        LearnedModel depleted = shipped().filter(m -> m.id().equals("depleted")).findFirst().orElseThrow();
        assertEquals(2, MachineGraph.folded(depleted).nodes().size());
        assertEquals(18, MachineGraph.full(depleted).nodes().size());
    }

    @Test
    void aSixtyStateMachineIsLaidOutWithoutOverlapsAtFullSize() {
        LearnedModel m = random(60, 7);
        MachineGraph g = MachineGraph.full(m);
        MachineLayout l = MachineLayout.of(g);
        assertEquals(60, l.states().size());
        assertEquals(List.of(), l.overlaps());
        assertInside(l);
        // Drawn at its natural size (the style sheet scales it to the page, "full size" shows it as it is).
        String svg = MachineDrawing.svg(l);
        assertTrue(svg.contains("width=\"" + (int) Math.ceil(l.width()) + "\""), svg.substring(0, 200));
    }

    /** Learned from the real recordings, where a self-loop's label stuck out past ELK's size of the graph. */
    @Test
    void machinesLearnedFromTheRealRecordingsAreDrawnInsideTheirBox() throws Exception {
        assumeTrue(Files.isDirectory(RealLogs.DIR), "no " + RealLogs.DIR + ", so no machine is learned from it");
        Abstraction a = AbstractionFiles.builtin("scope-fetch").orElseThrow();
        // The models the report of 'evaluate' draws: learned on every log, with the noise tuned as learn tunes it.
        ModelSet shown = new Evaluator(a, 0, Progress.NONE).crossValidate(ScenarioLayout.scan(RealLogs.DIR, a), 2)
                .models();
        for (LearnedModel m : shown.models()) {
            for (MachineGraph g : List.of(MachineGraph.folded(m), MachineGraph.full(m))) {
                MachineLayout l = MachineLayout.of(g);
                assertEquals(List.of(), l.overlaps(), m.id());
                assertInside(l);
            }
        }
    }

    /** Every text and every edge lies within the drawing, so that none is cut off at its edge. */
    private static void assertInside(MachineLayout l) {
        for (MachineLayout.Text t : l.texts()) {
            assertTrue(t.box().x() >= 0 && t.box().y() >= 0 && t.box().x() + t.box().w() <= l.width()
                    && t.box().y() + t.box().h() <= l.height(), t + " outside " + l.width() + "x" + l.height());
        }
        for (MachineLayout.Line e : l.edges()) {
            for (double[] p : e.points()) {
                assertTrue(p[0] >= 0 && p[1] >= 0 && p[0] <= l.width() && p[1] <= l.height(),
                        p[0] + "," + p[1] + " outside " + l.width() + "x" + l.height());
            }
        }
    }

    @Test
    void theLayoutIsDeterministic() throws Exception {
        LearnedModel m = shipped().filter(x -> x.id().equals("recharge-1")).findFirst().orElseThrow();
        assertEquals(MachineDrawing.svg(MachineGraph.full(m)), MachineDrawing.svg(MachineGraph.full(m)));
    }

    @Test
    void theOverlapCheckFindsOverlappingTexts() {
        MachineLayout.Box a = new MachineLayout.Box(10, 10, 100, 12);
        MachineLayout.Text t1 = new MachineLayout.Text("batteryStatus_i / o_batteryStatus_false", a, 20, true);
        MachineLayout.Text t2 = new MachineLayout.Text("batteryStatus_i / o_batteryStatus_true",
                new MachineLayout.Box(60, 15, 100, 12), 25, true);
        MachineLayout.Text apart = new MachineLayout.Text("level_i", new MachineLayout.Box(10, 22, 40, 12), 32, true);
        MachineLayout.State s = new MachineLayout.State(0, true, new MachineLayout.Box(140, 0, 34, 34));
        MachineLayout l = new MachineLayout(300, 100, List.of(s), List.of(), List.of(t1, t2, apart));
        List<String> found = l.overlaps();
        assertEquals(List.of("'batteryStatus_i / o_batteryStatus_false' overlaps 'batteryStatus_i / o_batteryStatus_true'",
                "'batteryStatus_i / o_batteryStatus_true' overlaps state s0"), found);
        assertFalse(a.overlaps(new MachineLayout.Box(110, 10, 5, 5)), "touching is not overlapping");
    }

    /**
     * A random machine over a learned machine's kind of alphabet: a chain of {@code Delta} steps through every
     * state, and queries that jump anywhere. Worse for a layout than a learned machine, which is
     * mostly a tree of query/reply pairs.
     */
    static LearnedModel random(int states, long seed) {
        List<String> inputs = List.of("Delta", "batteryStatus_i", "goTo_ch_i", "isAt_ch_i",
                "level_i_after_o_level_medium_five", "level_i_after_o_level_medium_six");
        Alphabet<String> alphabet = Alphabets.fromList(new ArrayList<>(inputs));
        CompactMealy<String, String> m = new CompactMealy<>(alphabet);
        Random r = new Random(seed);
        for (int i = 0; i < states; i++) {
            m.addState();
        }
        m.setInitialState(0);
        for (int i = 0; i < states; i++) {
            for (String in : inputs) {
                boolean delta = in.equals("Delta");
                if ((delta && i < states - 1) || r.nextDouble() < 0.4) {
                    int target = delta && i < states - 1 ? i + 1 : r.nextInt(states);
                    m.addTransition(i, in, target, delta ? "o_level_medium_" + r.nextInt(7) : "OK");
                }
            }
        }
        return new LearnedModel("random-" + states, "random", false, m, alphabet);
    }
}
