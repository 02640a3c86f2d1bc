package dev.predmon.forecast;

import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.List;
import java.util.function.BiConsumer;
import java.util.stream.Collectors;

import static dev.predmon.forecast.ForecastFileSections.readBody;
import static dev.predmon.forecast.ForecastFileSections.readRule;
import static dev.predmon.forecast.ForecastFileSections.readSurvival;
import static dev.predmon.forecast.ForecastFileSections.writeBody;
import static dev.predmon.forecast.ForecastFileSections.writeRule;
import static dev.predmon.forecast.ForecastFileSections.writeSurvival;

/**
 * One entry of {@code forecast.json}'s {@code properties}: a {@link PropertyModel} as {@code {"kind": ..., ...}}. The
 * one place that knows the kinds of the file: each {@link Kind} says its name, which record it writes and how it
 * reads one back. A new kind is one more {@link Kind} in {@link #KINDS}.
 */
final class PropertyCodec {

    /** How an entry of one kind reads: its property's id, where it is, and the unit of the file's times. */
    @FunctionalInterface
    interface Reader<T extends PropertyModel> {
        T read(String id, JsonAt at, String unit);
    }

    /**
     * One kind of entry.
     *
     * @param name  its {@code kind} in the file
     * @param type  the record it writes
     * @param write writes everything but the kind
     * @param read  reads what {@code write} wrote
     */
    record Kind<T extends PropertyModel>(String name, Class<T> type, BiConsumer<ObjectNode, T> write, Reader<T> read) {

        void writeOne(ObjectNode n, PropertyModel p) {
            n.put("kind", name);
            write.accept(n, type.cast(p));
        }
    }

    /** The kinds, in no particular order: each record has exactly one. */
    static final List<Kind<?>> KINDS = List.of(
            new Kind<>("bound", PropertyModel.OfBound.class, PropertyCodec::writeBound, PropertyCodec::readBound),
            new Kind<>("deadline", PropertyModel.OfDeadline.class, PropertyCodec::writeDeadline,
                    (id, at, unit) -> new PropertyModel.OfDeadline(id, readSurvival(at), readRule(at),
                            ScorecardJson.readScorecards(at))),
            new Kind<>("event", PropertyModel.OfEvent.class, PropertyCodec::writeEvent, PropertyCodec::readEvent));

    private PropertyCodec() {
    }

    /** {@code p} as the entry of its property under {@code properties}. */
    static void write(ObjectNode properties, PropertyModel p) {
        Kind<?> kind = KINDS.stream().filter(k -> k.type().isInstance(p)).findFirst()
                .orElseThrow(() -> new IllegalStateException("no kind writes " + p.getClass()));
        kind.writeOne(properties.putObject(p.id()), p);
    }

    /** The entry of property {@code id} at {@code at}, by its {@code kind}. */
    static PropertyModel read(String id, JsonAt at, String unit) {
        at.object();
        String name = at.text("kind");
        for (Kind<?> k : KINDS) {
            if (k.name().equals(name)) {
                return k.read().read(id, at, unit);
            }
        }
        throw at.get("kind").wrong("'" + name + "', expected one of " + KINDS.stream().map(Kind::name)
                .collect(Collectors.joining(", ")));
    }

    private static void writeBound(ObjectNode n, PropertyModel.OfBound b) {
        n.put("side", b.model().side());
        writeBody(n, b.model().model());
    }

    private static PropertyModel.OfBound readBound(String id, JsonAt at, String unit) {
        String side = at.text("side");
        ForecastModel m = readBody(at, ForecastModel.FORMAT, unit);
        return new PropertyModel.OfBound(id, at.get("side").built(() -> new BoundModel(side, m)));
    }

    private static void writeDeadline(ObjectNode n, PropertyModel.OfDeadline d) {
        writeSurvival(n, d.obligations());
        writeRule(n, d.rule());
        ScorecardJson.writeScorecards(n, d.scorecards());
    }

    /** An event forecast as a bound's body is written, or without one the counts that say why. */
    private static void writeEvent(ObjectNode n, PropertyModel.OfEvent e) {
        if (e.model().forecasts()) {
            writeBody(n, e.model().model());
        } else {
            n.put("runs", e.model().runs());
            n.put("violating", e.model().violating());
            n.put("noForecast", e.model().why());
        }
    }

    private static PropertyModel.OfEvent readEvent(String id, JsonAt at, String unit) {
        return new PropertyModel.OfEvent(id, event(at, ForecastModel.FORMAT, unit));
    }

    /** The event forecast at {@code at}: with a forecast when it has per-state tables, else its counts. */
    static EventModel event(JsonAt at, int format, String unit) {
        if (at.has("states")) {
            ForecastModel m = readBody(at, format, unit);
            return at.built(() -> new EventModel(m.runs(), m.violating(), m));
        }
        int runs = at.count("runs");
        int violating = at.count("violating");
        return at.built(() -> new EventModel(runs, violating, null));
    }
}
