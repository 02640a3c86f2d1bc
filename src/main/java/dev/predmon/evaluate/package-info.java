/**
 * Measures how the predictive monitor does on a user's own runs, by cross-validation or on a test set.
 */
package dev.predmon.evaluate;
