package dev.predmon.matching;

import dev.predmon.compact.IoPair;
import dev.predmon.model.LearnedModel;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

/**
 * Which models still match the run being watched, the thesis's MatchTracesRT made incremental: each compacted pair
 * advances every model still alive by its two Mealy steps ({@link ModelTracker}), a model is dropped at an input it
 * cannot take or when its discrepancies exceed the tolerance, and the match rule ({@link MatchRule}) is told what
 * is left. A scenario matches while any of its machines matches. Per pair the work is one step per model and the
 * state is constant (per model: state, discrepancy count, alive).
 */
public final class Matching {

    /**
     * What one pair left.
     *
     * @param eliminated   the models the pair eliminated, in model order
     * @param faultyAlive  the faulty scenarios some machine of which still matches, sorted
     * @param nominalAlive whether some nominal model still matches
     * @param ruleWarns    whether the match rule warns at this pair
     * @param contradicted whether every nominal model was eliminated by an output other than the one it predicted
     *                     (not by an input it has no transition for: a gap in what its training runs did, which
     *                     says the run is new to it, not that it is faulty)
     */
    public record Step(List<ModelTracker> eliminated, List<String> faultyAlive, boolean nominalAlive, boolean ruleWarns,
                boolean contradicted) {

        /** Whether no model, nominal or faulty, matches the run any more. */
        public boolean noMatch() {
            return !nominalAlive && faultyAlive.isEmpty();
        }
    }

    private final List<ModelTracker> trackers = new ArrayList<>();
    private final MatchRule rule;

    /**
     * @param tolerance discrepancies a model may accumulate and still match (0: exact matching)
     * @param confirm   pairs a faulty model must match after the last nominal model is eliminated before the match
     *                  rule warns
     */
    public Matching(List<LearnedModel> models, int tolerance, int confirm) {
        this.rule = new MatchRule(confirm);
        for (LearnedModel m : models) {
            trackers.add(new ModelTracker(m, tolerance));
        }
    }

    /** A new run: every model back to its initial state, alive. */
    public void reset() {
        trackers.forEach(ModelTracker::reset);
        rule.reset();
    }

    /** Advances every model still alive by {@code pair}. */
    public Step pair(IoPair pair) {
        List<ModelTracker> eliminated = new ArrayList<>();
        for (ModelTracker t : trackers) {
            if (t.alive() && !t.pair(pair.input(), pair.output())) {
                eliminated.add(t);
            }
        }
        List<String> faultyAlive = faultyAlive();
        boolean nominalAlive = nominalAlive();
        boolean contradicted = !nominalAlive && trackers.stream().filter(t -> !t.model().faulty())
                .allMatch(t -> t.elimination().expected() != null);
        return new Step(eliminated, faultyAlive, nominalAlive, rule.warns(nominalAlive, !faultyAlive.isEmpty()),
                contradicted);
    }

    /** Whether some nominal model still matches the run. Asked after every record: a loop, no allocation. */
    public boolean nominalAlive() {
        for (int i = 0; i < trackers.size(); i++) {
            ModelTracker t = trackers.get(i);
            if (t.alive() && !t.model().faulty()) {
                return true;
            }
        }
        return false;
    }

    /** The faulty scenarios some machine of which still matches the run, sorted. */
    public List<String> faultyAlive() {
        TreeSet<String> alive = new TreeSet<>();
        trackers.stream().filter(t -> t.alive() && t.model().faulty()).forEach(t -> alive.add(t.model().scenario()));
        return List.copyOf(alive);
    }

    /**
     * The faulty scenario the run is most like: the first of {@code faultyAlive} (the faulty scenarios still
     * matching), else the one whose machine was eliminated last in this run (it matched the run longest); null when
     * the models have no faulty machine.
     */
    public String likeliestFaulty(List<String> faultyAlive) {
        if (!faultyAlive.isEmpty()) {
            return faultyAlive.get(0);
        }
        ModelTracker longest = null;
        for (ModelTracker t : trackers) {
            if (t.model().faulty() && t.elimination() != null
                    && (longest == null || t.elimination().step() > longest.elimination().step())) {
                longest = t;
            }
        }
        return longest == null ? null : longest.model().scenario();
    }

    /** Every model's tracker, in model order. */
    public List<ModelTracker> trackers() {
        return List.copyOf(trackers);
    }
}
