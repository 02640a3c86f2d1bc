package dev.predmon.abstraction;

/** Which side of the skill-component interface a symbol belongs to: a query (input) or its answer (output). */
public enum Direction {
    INPUT, OUTPUT
}
