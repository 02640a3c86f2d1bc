package dev.predmon.model;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.PropertyModel;
import dev.predmon.forecast.PropertyParts;
import dev.predmon.forecast.StateStats;
import dev.predmon.property.Bound;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Checks a forecast against the models beside it: its per-property parts cover the abstraction's properties as learn
 * writes them and fit them, its first floor's among them ({@link PropertyParts}), and every property's forecast keeps
 * statistics only for machines the index lists and for states those machines have. A forecast that does not fit would give every run of a
 * machine it does not know the base rate, warn on a bound nobody watches, or drop a property's warnings unseen.
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
        try {
            PropertyParts.check(forecast, abstraction);
        } catch (IllegalArgumentException e) {
            throw new BadInputException(file + ": " + e.getMessage() + "; relearn");
        }
        double bound = abstraction.safety().map(Bound::floor).orElse(Double.NaN);
        if (Double.compare(forecast.limit(), bound) != 0) {
            throw new BadInputException(file + ": limit " + shown(forecast.limit()) + " is not the bound of the "
                    + "abstraction's safety property (" + shown(bound) + "); relearn with the abstraction in use");
        }
        Map<String, Integer> sizes = new HashMap<>();
        models.forEach(m -> sizes.put(m.id(), m.machine().size()));
        boolean named = forecast.format() >= ForecastModel.FORMAT;
        if (!named) {
            states(file, indexFile, "", forecast, sizes);
        }
        for (PropertyModel p : forecast.properties()) {
            String where = "'" + (named ? "properties." + p.id() : (p instanceof PropertyModel.OfBound ? "bounds."
                    : "events.") + p.id()) + ".states': ";
            if (p instanceof PropertyModel.OfBound b) {
                states(file, indexFile, where, b.model().model(), sizes);
            } else if (p instanceof PropertyModel.OfEvent e && e.model().forecasts()) {
                states(file, indexFile, where, e.model().model(), sizes);
            }
        }
    }

    /** {@code forecast} keeps statistics only for machines the index lists ({@code sizes}) and states they have. */
    private static void states(Path file, Path indexFile, String where, ForecastModel forecast,
                               Map<String, Integer> sizes) throws BadInputException {
        for (Map.Entry<String, Map<Integer, StateStats>> machine : forecast.states().entrySet()) {
            Integer size = sizes.get(machine.getKey());
            if (size == null) {
                throw new BadInputException(file + ": " + where + "machine '" + machine.getKey() + "' is not one "
                        + indexFile.getFileName() + " lists; relearn");
            }
            for (int state : machine.getValue().keySet()) {
                if (state < 0 || state >= size) {
                    throw new BadInputException(file + ": " + where + "state " + state + " of machine '"
                            + machine.getKey() + "' is not in its DOT file (states 0 to " + (size - 1) + "); relearn");
                }
            }
        }
    }

    private static String shown(double v) {
        return Double.isNaN(v) ? "none" : Double.toString(v);
    }
}
