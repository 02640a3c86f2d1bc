/**
 * The abstraction of the skill-component interface: turns each log record into an input or output symbol, or
 * drops it, by the rules of an abstraction file, and carries the rules that cut a log into runs and define the
 * safety property.
 */
package dev.predmon.abstraction;
