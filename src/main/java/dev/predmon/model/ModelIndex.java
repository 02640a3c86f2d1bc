package dev.predmon.model;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.databind.JsonNode;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;

/**
 * The contents of {@code models/index.json}: what was learned, from what, with which abstraction.
 *
 * @param format      file format version, {@value #FORMAT}
 * @param abstraction the abstraction the models were learned with
 * @param alphabet    the Mealy input alphabet (abstraction inputs plus {@code Delta}), sorted
 * @param scenarios   the scenarios, sorted by name
 * @param forecast    the file of the forecast's statistics ({@code forecast.json}), or null in a directory learned
 *                    before forecasts were (it loads; the forecast is then off until the next learn)
 * @param learnId     what ties the directory's files together, written by {@code learn} (a hash of the abstraction's
 *                    fingerprint and the DOT files, also written in {@code forecast.json}); null until written
 */
public record ModelIndex(int format, AbstractionInfo abstraction, List<String> alphabet, List<Scenario> scenarios,
                         @JsonInclude(JsonInclude.Include.NON_NULL) String forecast,
                         @JsonInclude(JsonInclude.Include.NON_NULL) String learnId) {

    /** An index without a forecast. */
    public ModelIndex(int format, AbstractionInfo abstraction, List<String> alphabet, List<Scenario> scenarios) {
        this(format, abstraction, alphabet, scenarios, null, null);
    }

    /** An index as learned, before it is written (the learn id is set by {@link ModelStore#write}). */
    public ModelIndex(int format, AbstractionInfo abstraction, List<String> alphabet, List<Scenario> scenarios,
                      String forecast) {
        this(format, abstraction, alphabet, scenarios, forecast, null);
    }

    /** This index with the given forecast file and learn id. */
    ModelIndex with(String forecastFile, String id) {
        return new ModelIndex(format, abstraction, alphabet, scenarios, forecastFile, id);
    }

    /** Current index format. */
    public static final int FORMAT = 1;

    /**
     * How learn names a scenario (it becomes a file name, a symbol in reports and a hook's environment): letters,
     * digits, {@code _}, {@code -} and {@code .}, not starting with {@code -} or {@code .}.
     */
    public static final Pattern SCENARIO_NAME = Pattern.compile("[A-Za-z0-9_][A-Za-z0-9_.-]*");

    /**
     * The abstraction, embedded so that a model directory is self-describing.
     *
     * @param hysteresis the hysteresis {@code learn} estimated from the training runs' sensor noise, by continuous
     *                   rule input, applied by every command that uses these models; absent when none was (noise-free
     *                   sensors), so that such an index is unchanged
     */
    public record AbstractionInfo(String name, String fingerprint, JsonNode definition,
                                  @JsonInclude(JsonInclude.Include.NON_EMPTY) Map<String, Double> hysteresis) {

        public AbstractionInfo {
            hysteresis = hysteresis == null ? Map.of() : Map.copyOf(new TreeMap<>(hysteresis));
        }
    }

    /**
     * One scenario and its machines.
     *
     * @param violates the id of the property a faulty scenario's runs violate, as its {@code scenario.json} names it;
     *                 absent (null) for the property the forecast follows, so that such an index is unchanged
     */
    public record Scenario(String name, boolean faulty, String description, int samples, List<Model> models,
                           @JsonInclude(JsonInclude.Include.NON_NULL) String violates) {

        /** A scenario about the property the forecast follows. */
        public Scenario(String name, boolean faulty, String description, int samples, List<Model> models) {
            this(name, faulty, description, samples, models, null);
        }
    }

    /**
     * One machine. Nothing that varies from run to run (such as the time learning took) is stored, so that the same
     * logs give the same index byte for byte and a model directory under version control changes only when the
     * models do.
     *
     * @param file    DOT file name inside the model directory
     * @param states  number of states
     * @param samples number of logs it was learned from
     * @param logs    those logs' file names
     */
    public record Model(String file, int states, int samples, List<String> logs) {
    }
}
