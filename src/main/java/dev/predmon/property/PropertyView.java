package dev.predmon.property;

import java.util.List;

/**
 * The {@link PropertyChecker} of a run as its readers see it, read-only: for each property, after the last record,
 * whether it is violated now, whether it is in scope and the value it read. The one reader and judge of a property's
 * value: whoever shows, labels or scores a property asks it instead of reading the record again.
 */
public interface PropertyView {

    /** The properties, in order. */
    List<Property> properties();

    /** The value the last record gave property {@code index} within its scope (a bound's), or NaN. */
    double reading(int index);

    /** The value the last record carried for bound {@code index}, whatever its scope; NaN when none. */
    double value(int index);

    /** Whether property {@code index} is checked now (its scope is open). */
    boolean inScope(int index);

    /** Whether property {@code index} is violated now. */
    boolean violatedNow(int index);

    /** The verdict of property {@code index} on the run so far. */
    Verdict verdict(int index);

    /** The position of the property with id {@code id}, or -1. */
    default int indexOf(String id) {
        List<Property> all = properties();
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).id().equals(id)) {
                return i;
            }
        }
        return -1;
    }
}
