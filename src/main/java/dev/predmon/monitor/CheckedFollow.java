package dev.predmon.monitor;

import dev.predmon.parse.LogRecord;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;

/**
 * A property checked but not forecast (an absence, a precedence, a response the training runs never owed): its
 * violation, the matching's warning of it and the end of its alarms, as every follower has them ({@link FollowBase}).
 */
final class CheckedFollow extends FollowBase {

    CheckedFollow(int index, Property property, FollowContext c) {
        super(index, property, c);
    }

    @Override
    void follow(PropertyChecker checker, LogRecord r, boolean in) {
        // no forecast: nothing more than the checker's verdict
    }
}
