/**
 * Safety properties: what a run must satisfy, of several kinds ({@link Property}), read from records by one reader
 * ({@link ValueReader}) and checked incrementally, with constant state per property, by a {@link PropertyChecker}
 * per run that gives each property its {@link Verdict}. Sits on {@code parse}: a property speaks of log records,
 * not of the abstraction's symbols, and the abstraction file carries the properties.
 */
package dev.predmon.property;
