/**
 * The abstraction file format: reading, validating and writing abstraction JSON, with one-line errors naming file
 * and line, and the built-in abstractions ({@link dev.predmon.abstraction.file.AbstractionFiles} is the entry point).
 */
package dev.predmon.abstraction.file;
