/**
 * Simulates the thesis's case study (a behaviour tree driving a battery and a navigation component) and writes
 * its runs as YARP monitor logs with their ground truth (the scenario, what each novelty did, and which properties
 * the run violated and where), for {@code simulate}, the sample logs, the tests and the benchmarks.
 */
package dev.predmon.simulate;
