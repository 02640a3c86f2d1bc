package dev.predmon.model;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.StateStats;
import dev.predmon.property.Bound;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Checks a forecast against the models beside it: its property's bound is the abstraction's, and it keeps
 * statistics only for machines the index lists and for states those machines have. A forecast that does not fit
 * would give every run of a machine it does not know the base rate, or warn on a bound nobody watches.
 */
final class ForecastCheck {

    private ForecastCheck() {
    }

    /**
     * @param file      the forecast's file, named in the message
     * @param indexFile the index, named in the message
     * @throws BadInputException one line naming {@code file} and what disagrees
     */
    static void check(Path file, Path indexFile, ForecastModel forecast, List<LearnedModel> models,
                      Abstraction abstraction) throws BadInputException {
        double bound = abstraction.safety().map(Bound::floor).orElse(Double.NaN);
        if (Double.compare(forecast.limit(), bound) != 0) {
            throw new BadInputException(file + ": limit " + shown(forecast.limit()) + " is not the bound of the "
                    + "abstraction's safety property (" + shown(bound) + "); relearn with the abstraction in use");
        }
        Map<String, Integer> sizes = new HashMap<>();
        models.forEach(m -> sizes.put(m.id(), m.machine().size()));
        for (Map.Entry<String, Map<Integer, StateStats>> machine : forecast.states().entrySet()) {
            Integer size = sizes.get(machine.getKey());
            if (size == null) {
                throw new BadInputException(file + ": machine '" + machine.getKey() + "' is not one "
                        + indexFile.getFileName() + " lists; relearn");
            }
            for (int state : machine.getValue().keySet()) {
                if (state < 0 || state >= size) {
                    throw new BadInputException(file + ": state " + state + " of machine '" + machine.getKey()
                            + "' is not in its DOT file (states 0 to " + (size - 1) + "); relearn");
                }
            }
        }
    }

    private static String shown(double v) {
        return Double.isNaN(v) ? "none" : Double.toString(v);
    }
}
