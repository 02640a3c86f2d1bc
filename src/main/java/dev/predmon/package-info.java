/**
 * predmon, predictive runtime monitoring of robots from learned Mealy machines; this package holds only
 * {@link BadInputException}, the checked exception for bad external input (a log, a model directory, an abstraction
 * or scenario file), whose one-line message the command line shows the user.
 */
package dev.predmon;
