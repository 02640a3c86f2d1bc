/**
 * A model directory on disk: reads, checks and writes the learned machines (DOT files), {@code index.json} and
 * the abstraction they were learned with, never destroying a file predmon did not write.
 */
package dev.predmon.model;
