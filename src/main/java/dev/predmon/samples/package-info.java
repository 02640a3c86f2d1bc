/**
 * Writes and reads the Mealy samples that {@code learn} gives LearnLib as plain text, for {@code export-samples}.
 */
package dev.predmon.samples;
