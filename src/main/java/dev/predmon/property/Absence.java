package dev.predmon.property;

/**
 * An event never happens ({@code historically(not event)}): the navigation never aborts, that is no {@code getStatus}
 * reply {@code 3}. Violated at the first occurrence.
 */
public record Absence(String id, String name, String action, Scope scope, Event event) implements Property {

    @Override
    public String kind() {
        return "absence";
    }
}
