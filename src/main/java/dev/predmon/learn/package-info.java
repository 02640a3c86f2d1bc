/**
 * Learns, from a directory of logs (sorted into scenarios, or labelled by the safety monitor), one Mealy machine per
 * conflict-free group of a scenario's runs (LearnLib's passive RPNI) and the forecast's statistics that go with them.
 */
package dev.predmon.learn;
