/**
 * The thesis's mapping from a trace of query/reply pairs to the input and output words of a Mealy machine, the
 * form in which runs are learned and matched.
 */
package dev.predmon.mealy;
