package dev.predmon.forecast;

/**
 * Which parts of a bound's warning rule warn, as its cross-validation chose them ({@link CrossValidation}).
 *
 * @param baseline whether the raw-value baseline warns in place of the forecast's rule (below the lowest value any
 *                 safe training run read), because the forecast's rule did worse on the same held-out folds
 * @param matching whether the thesis's matching warns too (every nominal machine contradicted while a faulty one
 *                 matches): only where it did better on the held-out folds than the rule without it
 */
public record Clauses(boolean baseline, boolean matching) {

    /** Every clause of the forecast's rule: what models learned before the choice warn by. */
    public static final Clauses ALL = new Clauses(false, true);
    /** The forecast's rule without the matching clause. */
    public static final Clauses NO_MATCHING = new Clauses(false, false);
    /** The raw-value baseline alone. */
    public static final Clauses BASELINE = new Clauses(true, false);
}
