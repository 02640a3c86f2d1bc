package dev.predmon.property;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The values the properties of one checker read, each distinct {@link ValueReader} read once per record: a bound and
 * a response triggered by a condition on the same value (the built-ins' battery level) share one reading, and so does
 * whoever asks the checker for it afterwards (the forecast).
 */
final class Readings {

    private final ValueReader[] readers;
    private final double[] values;

    /** The distinct values read by the bounds and the conditions of {@code properties}. */
    Readings(List<Property> properties) {
        List<ValueReader> distinct = new ArrayList<>();
        for (Property p : properties) {
            ValueReader v = p instanceof Bound b ? b.value()
                    : p instanceof Response q && q.condition() != null ? q.condition().value() : null;
            if (v != null && !distinct.contains(v)) {
                distinct.add(v);
            }
        }
        this.readers = distinct.toArray(new ValueReader[0]);
        this.values = new double[readers.length];
        Arrays.fill(values, Double.NaN);
    }

    /** The slot of {@code reader}'s value. */
    int slot(ValueReader reader) {
        for (int i = 0; i < readers.length; i++) {
            if (readers[i].equals(reader)) {
                return i;
            }
        }
        throw new IllegalArgumentException("no such value: " + reader.describe());
    }

    /** Reads every value from {@code r}, the next record. */
    void read(LogRecord r) {
        boolean reply = r.kind() == RecordKind.REPLY; // only a reply carries a value
        for (int i = 0; i < readers.length; i++) {
            values[i] = reply ? readers[i].valueOf(r) : Double.NaN;
        }
    }

    /** The value in {@code slot} that the last record carried ({@link ValueReader#valueOf}), or NaN. */
    double value(int slot) {
        return values[slot];
    }
}
