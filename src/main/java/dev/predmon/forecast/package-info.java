/**
 * The forecast: from per-state statistics learned with the models, how likely the run is to violate the safety
 * property and how soon, after every compacted pair, also through behaviour no model has seen.
 */
package dev.predmon.forecast;
