/**
 * Writes the files predmon produces, each completely or not at all, and checks before a command's work where its
 * outputs may go: never over an input, never over a file predmon did not write.
 */
package dev.predmon.files;
