/**
 * Parses predmon's command line and hands each command to the package that does its work.
 */
package dev.predmon.cli;
