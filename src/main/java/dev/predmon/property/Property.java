package dev.predmon.property;

/**
 * A named safety property of a robot, one of four kinds, each with past-time temporal-logic semantics (as MOON and
 * Reelay check them; Dwyer's specification patterns compile to them). Every kind is a safety property: a violation
 * on a prefix of a run is final.
 * <ul>
 *   <li>{@link Bound}: a numeric value stays within a floor and/or a ceiling, {@code historically(floor <= v <= ceiling)};</li>
 *   <li>{@link Absence}: an event never happens, {@code historically(not e)};</li>
 *   <li>{@link Response}: after a trigger a response comes within a deadline,
 *       {@code historically(not(not response since[>T] trigger))};</li>
 *   <li>{@link Precedence}: an event never happens before another one, {@code historically(b -> once a)}.</li>
 * </ul>
 * Each may hold only within a {@link Scope}.
 */
public sealed interface Property permits Bound, Absence, Response, Precedence {

    /** Short and stable: names the property in events, hooks and truth files ({@code battery}, {@code no-abort}). */
    String id();

    /** The property in words, shown to users ({@code battery level >= 20%}). */
    String name();

    /** What an operator should do when it is predicted to fail or fails, in words, or null when none is given. */
    String action();

    /** Where the property is checked: {@link Scope#GLOBAL} for the whole run. */
    Scope scope();

    /** The kind as the abstraction file names it: {@code bound}, {@code absence}, {@code response}, {@code precedence}. */
    String kind();
}
