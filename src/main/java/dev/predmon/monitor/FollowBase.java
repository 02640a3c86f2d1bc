package dev.predmon.monitor;

import dev.predmon.forecast.ForecastWords;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Verdict;

/**
 * What every property's follower shares, written once: as the checker judged a record, the property's violation
 * ({@link MonitorEvent.Violation}), its end when the property holds again (cause {@code property}), the end of any
 * alarm of it when its scope closes ({@value #SCOPE}: out of its scope it cannot be violated) or when its run ends
 * ({@value #RUN_ENDED}: a new run began, or the log was restarted), the thesis's matching warning of it, and its
 * status. A warning is raised only while no warning of the property is up and, under the forecast rule, never while
 * it is violated.
 */
abstract class FollowBase implements PropertyFollow {

    /** The cause of a recovery that the property's scope closed. */
    static final String SCOPE = "scope";
    /** The cause of a recovery that the run ended (a new run began, or the log was restarted) with an alarm up. */
    static final String RUN_ENDED = MonitorEvent.Recovered.RUN_ENDED;

    final int index;
    final Property property;
    final FollowContext c;
    /** The warning of the property up now, or null. */
    MonitorEvent.Warning active;
    /** Whether the property is violated now, as the checker judged the last record. */
    boolean violated;
    /** Whether its scope is open, as the checker judged the last record. */
    boolean open;

    FollowBase(int index, Property property, FollowContext c) {
        this.index = index;
        this.property = property;
        this.c = c;
        this.open = property.scope().global();
    }

    /**
     * The property's forecast and warning at record {@code r}, after its violation or recovery there ({@code in}:
     * whether its scope is open after {@code r}).
     */
    abstract void follow(PropertyChecker checker, LogRecord r, boolean in);

    /** Its scope opened at {@code r}: a forecast starts over from the states the run is in. */
    void opened(LogRecord r) {
    }

    /** The property holds again after its violation, or an alarm of it ended: a forecast starts over. */
    void startOver() {
    }

    @Override
    public final void record(PropertyChecker checker, LogRecord r) {
        boolean in = checker.inScope(index);
        if (in && !open) {
            open = true;
            opened(r);
        }
        boolean before = violated;
        Verdict.Violated made = violation(checker, r);
        if (made != null) {
            active = null; // the violation overtakes the warning
        } else if (checker.holdsAgain(index)) {
            double v = checker.reading(index);
            startOver();
            ended(r, "property", v, label() + " holds again (" + ForecastWords.fixed(v, 2) + ")");
        }
        follow(checker, r, in);
        if (!in && open) {
            open = false;
            if (active != null || (before && !violated && made == null)) {
                ended(r, SCOPE, lastValue(), label() + ": out of its scope at " + property.scope().until().describe()
                        + "; not checked until " + property.scope().from().describe() + " again");
            }
            active = null;
        }
    }

    @Override
    public void overdue(PropertyChecker checker, LogRecord first) {
        if (violation(checker, first) != null) {
            active = null;
        }
    }

    /** The checker's judgement of the last record: its violation, told when it made one, or null. */
    private Verdict.Violated violation(PropertyChecker checker, LogRecord r) {
        violated = checker.violatedNow(index);
        Verdict.Violated made = checker.violatedAt(index);
        if (made != null) {
            c.events.accept(new MonitorEvent.Violation(made.time(), made.line(), property.id(), property.name(),
                    made.value(), made.before(), made.what(), r.clock(), c.now.run, headline()));
        }
        return made;
    }

    /** The alarm of the property ended at {@code r}: told. */
    final void ended(LogRecord r, String cause, double value, String reason) {
        active = null;
        c.events.accept(new MonitorEvent.Recovered(r.time(), r.line(), cause, value, reason, r.clock(), c.now.run,
                property.id()));
    }

    /** Raises {@code w}, a warning of the property. */
    final void warn(MonitorEvent.Warning w) {
        active = w;
        c.events.accept(w);
    }

    @Override
    public boolean takesMatching() {
        return active == null && (!c.forecastRule() || !violated);
    }

    @Override
    public void matchingWarned(MonitorEvent.Warning w) {
        active = w;
    }

    @Override
    public Double value() {
        return null;
    }

    /** The property's last value, NaN without one (what a recovery reports). */
    double lastValue() {
        Double v = value();
        return v == null ? Double.NaN : v;
    }

    @Override
    public void runEnded(LogRecord last, String why) {
        if (active != null || violated) {
            ended(last, RUN_ENDED, lastValue(), label() + ": " + why);
        }
    }

    @Override
    public void reset() {
        active = null;
        violated = false;
        open = property.scope().global();
    }

    /** Whether a warning of the property is up now (raised, and neither recovered from nor overtaken). */
    boolean warned() {
        return active != null && !violated;
    }

    @Override
    public PropertyStatus status(PropertyChecker checker) {
        return new PropertyStatus(property, checker.verdict(index), PropertyStatus.Model.NONE, warned(), null, null);
    }

    /** Whether the property is the one the run's outcome headlines. */
    final boolean headline() {
        return property.id().equals(c.headline);
    }

    /** The property as words name it: {@code 'battery level >= 20%' (battery)}. */
    final String label() {
        return "'" + property.name() + "' (" + property.id() + ")";
    }
}
