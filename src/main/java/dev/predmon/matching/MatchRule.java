package dev.predmon.matching;

/**
 * The thesis's warning rule (Algorithm 8, the match rule) over one run, pair by pair: it warns once every nominal
 * model is eliminated while a faulty one still matches, and a faulty model has matched {@code confirm} more pairs
 * since ({@code confirm = 0} is Algorithm 8 itself). Silent once no model matches. The one implementation of the rule:
 * {@code watch} applies it as records come, and {@code learn} replays it on the held-out runs that choose the
 * forecast's threshold.
 *
 * <p>Why {@code confirm}: the nominal models are learned from finitely many runs, so a nominal run that does something
 * no training run did (its battery crosses a band while the robot grasps, say) eliminates them all; a faulty model
 * that happens to allow that step would then warn on no evidence but the novelty. With {@code confirm = 1} the faulty
 * model must also predict what happens next.
 *
 * <p>Which models are still alive is for the caller to say, after each pair: how a model is eliminated (exactly, or
 * after more discrepancies than a threshold) is the matcher's business, not the rule's.
 */
public final class MatchRule {

    private final int confirm;
    /** Pairs matched since every nominal model was eliminated with a faulty one alive; -1 before. */
    private long sinceNominalGone = -1;

    /** @param confirm pairs a faulty model must match after the last nominal model is eliminated before the warning */
    public MatchRule(int confirm) {
        if (confirm < 0) {
            throw new IllegalArgumentException("confirm must be at least 0, got " + confirm);
        }
        this.confirm = confirm;
    }

    /** A new run: nothing eliminated yet. */
    public void reset() {
        sinceNominalGone = -1;
    }

    /**
     * Takes the models alive after the next pair of the run and says whether the rule warns there (again at every
     * later pair that still satisfies it: the caller warns once).
     *
     * @param nominalAlive whether some nominal model still matches the run
     * @param faultyAlive  whether some faulty model still matches the run
     */
    public boolean warns(boolean nominalAlive, boolean faultyAlive) {
        boolean onlyFaulty = !nominalAlive && faultyAlive;
        if (onlyFaulty) {
            sinceNominalGone++;
        }
        return onlyFaulty && sinceNominalGone >= confirm;
    }
}
