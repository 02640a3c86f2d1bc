/**
 * Delivers the monitor's warnings and violations to the robot by running the user's {@code --on-warning} and
 * {@code --on-violation} shell commands, with the event on standard input and in environment variables.
 */
package dev.predmon.hooks;
