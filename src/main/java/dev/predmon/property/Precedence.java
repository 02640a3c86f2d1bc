package dev.predmon.property;

/**
 * An event never happens before another one: {@code then} only after {@code first}
 * ({@code historically(then -> once first)}). Violated at an occurrence of {@code then} when {@code first} has not
 * occurred yet (in the scope's segment); a record that is both is not a violation.
 */
public record Precedence(String id, String name, String action, Scope scope, Event first, Event then)
        implements Property {

    @Override
    public String kind() {
        return "precedence";
    }
}
