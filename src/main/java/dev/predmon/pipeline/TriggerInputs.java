package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Response;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Where a run was when each obligation of a bounded response began: the condition its deadline forecast is judged
 * under ({@code forecast.Survival#at}). The condition is the Mealy input the trigger record maps to (the skill asked
 * for, and where to: {@code goTo_ki_i}), after the input of the property's previous trigger record in the run
 * ({@code goTo_ch_i>goTo_ki_i}: the way to the tour location after a turn to the charger, not the first one;
 * {@code start>goTo_ki_i} for the first). Inputs mean the same in every model learned with the abstraction, so the
 * condition is the same in each fold of the cross-validation and in {@code watch}; a machine's state number is not.
 *
 * <p>Learning ({@link Traces}) and the monitor keep one each and call {@link #record} after their checker took each
 * record. The abstraction classifies only trigger records (a few per run). Per property, the state is one condition
 * per open obligation.
 */
public final class TriggerInputs {

    /** What a run's first trigger comes after. */
    public static final String START = "start";
    /** Between the previous trigger's input and this one's. */
    public static final String AFTER = ">";

    private final Abstraction abstraction;
    private final Response[] responses;
    /** Per property, the condition each open obligation began under, by the line of its trigger. */
    private final Map<Long, String>[] began;
    /** Per property, the input of its last trigger record in the run, or null before one. */
    private final String[] last;

    public TriggerInputs(Abstraction abstraction, List<Property> properties) {
        this.abstraction = abstraction;
        int n = properties.size();
        this.responses = new Response[n];
        @SuppressWarnings("unchecked")
        Map<Long, String>[] b = new Map[n];
        this.began = b;
        for (int i = 0; i < n; i++) {
            if (properties.get(i) instanceof Response r) {
                responses[i] = r;
                began[i] = new HashMap<>();
            }
        }
        this.last = new String[n];
    }

    /** After {@code checker} took {@code r}: notes the obligations that began at it, and its trigger input. */
    public void record(PropertyChecker checker, LogRecord r) {
        String input = null;
        boolean classified = false;
        for (int i = 0; i < responses.length; i++) {
            Response p = responses[i];
            if (p == null) {
                continue;
            }
            long opened = checker.opened(i);
            int asked = checker.triggered(i); // the checker's answer, when its step asked it: one match a record
            boolean trigger = p.trigger() != null && (asked >= 0 ? asked == 1 : p.trigger().matches(r));
            if ((trigger || opened >= 0) && !classified) {
                input = RunTiming.inputOf(abstraction, r);
                classified = true;
            }
            if (opened >= 0) {
                began[i].put(opened, input == null ? null : (last[i] == null ? START : last[i]) + AFTER + input);
            }
            if (trigger && input != null) {
                last[i] = input;
            }
        }
    }

    /**
     * The condition property {@code index}'s obligation opened by the trigger at {@code line} began under, null when
     * its trigger maps to no input (or no such obligation is open).
     */
    public String began(int index, long line) {
        return began[index] == null ? null : began[index].get(line);
    }

    /** Property {@code index}'s obligation opened at {@code line} ended (as the checker tells it, during a record). */
    public void closed(int index, long line) {
        if (began[index] != null) {
            began[index].remove(line);
        }
    }

    /** A new run. */
    public void reset() {
        for (Map<Long, String> m : began) {
            if (m != null) {
                m.clear();
            }
        }
        Arrays.fill(last, null);
    }

    /** The part of {@code condition} after the previous trigger's input: the trigger's input alone. */
    public static String input(String condition) {
        int at = condition == null ? -1 : condition.lastIndexOf(AFTER);
        return at < 0 ? condition : condition.substring(at + AFTER.length());
    }
}
