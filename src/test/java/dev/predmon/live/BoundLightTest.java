package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.event.LogEvent;
import dev.predmon.forecast.Forecast;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PropertyStatus;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.Verdict;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A bound property other than the forecast's has a light with its own value forecast: green with its probability and
 * time, yellow while its warning is up, green again with its recovery; the tile's own alarm, forecast and metric (the
 * forecast's property's) stay as they were.
 */
class BoundLightTest {

    private static final Abstraction A = AbstractionFiles.defaults();
    private static final Bound BATTERY = A.safety().orElseThrow();
    private static final Bound RESERVE = new Bound("reserve", "battery reserve >= 40%", "cut the tour short",
            BATTERY.value(), 40);
    private final AtomicLong now = new AtomicLong(1_000_000);

    private static List<Property> properties() {
        List<Property> all = new ArrayList<>(A.properties());
        all.add(RESERVE);
        return all;
    }

    /** Every property holding; the reserve forecast by {@code reserve}, warned when {@code warned}. */
    private static List<PropertyStatus> statuses(Forecast reserve, boolean warned) {
        List<PropertyStatus> all = new ArrayList<>();
        for (Property p : properties()) {
            if (p.id().equals("reserve")) {
                all.add(new PropertyStatus(p, Verdict.HOLDS, PropertyStatus.Model.FORECAST, warned, null, null,
                        reserve));
            } else {
                all.add(new PropertyStatus(p, Verdict.HOLDS, p.id().equals("battery") ? PropertyStatus.Model.FORECAST
                        : PropertyStatus.Model.NONE, false, null, null));
            }
        }
        return all;
    }

    private static JsonNode light(Board b, String id) {
        for (JsonNode l : b.status("a.log").get("logs").get(0).get("properties")) {
            if (l.get("property").asText().equals(id)) {
                return l;
            }
        }
        throw new AssertionError(id);
    }

    @Test
    void aReserveIsForecastWarnedAndRecoveredOnItsOwnLight() {
        Board b = new Board(List.<LearnedModel>of(), A.safety(), properties(), Duration.ofSeconds(10), now::get,
                RobotNames.byFile(), List.of());
        Tile t = b.tile("a.log");
        Judged.record(t, new Records().at(1).level(55).list().get(1));
        Forecast f = new Forecast(0.62, 8.5, 6.5, 12.3, Forecast.Basis.MATCHED, null, 17, 11, 55.0, -1.8, "s");
        t.properties(statuses(f, false));
        JsonNode reserve = light(b, "reserve");
        assertEquals("green", reserve.get("light").asText());
        assertEquals("forecast", reserve.get("model").asText());
        assertEquals(0.62, reserve.get("forecast").get("probability").asDouble());
        assertEquals(55.0, reserve.get("forecast").get("value").asDouble());
        assertEquals("P(violation) 62%, no warning (skill not measured)",
                reserve.get("forecastWords").asText());

        b.event(t, LogEvent.of("a.log", new MonitorEvent.ForecastChanged(1, 30, f, Clock.SECONDS, 0, "reserve")));
        JsonNode tile = b.status("a.log").get("logs").get(0);
        assertTrue(tile.get("forecast").isNull(), "the tile's forecast is the battery's: " + tile.get("forecast"));

        String reason = "'battery reserve >= 40%' (reserve): P(violation) 0.62 reaches the warning threshold 0.53; "
                + "do now: cut the tour short";
        b.event(t, LogEvent.of("a.log", new MonitorEvent.Warning(1, 31, List.of(), 55.0, 4, Clock.SECONDS, 0,
                WarningRule.FORECAST, f, reason, MonitorEvent.Clause.FORECAST, null, "reserve")));
        t.properties(statuses(f, true));
        reserve = light(b, "reserve");
        assertEquals("yellow", reserve.get("light").asText());
        assertEquals(reason, reserve.get("words").asText());
        assertEquals("P(violation) 62%, about 8.50 s to the violation (6.50-12.3 s) (skill not measured)",
                reserve.get("forecastWords").asText(), "a warned forecast says when the violation comes");
        tile = b.status("a.log").get("logs").get(0);
        assertEquals("warning", tile.get("state").asText(), "the robot's state is its worst property's: " + tile);
        assertEquals("ok", tile.get("forecastState").asText(), "the battery's alarm is untouched: " + tile);
        assertEquals("[\"reserve\"]", tile.get("warned").toString());
        String metrics = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        assertTrue(metrics.contains("predmon_property_warnings_total{log=\"a.log\",property=\"reserve\",robot=\"a\"}"
                + " 1.0"), metrics);
        assertTrue(metrics.contains("predmon_warnings_total{log=\"a.log\",property=\"battery level >= 20% (thesis "
                + "3.3.1)\",robot=\"a\"} 0.0"), "not the battery's warning: " + metrics);

        b.event(t, LogEvent.of("a.log", new MonitorEvent.Recovered(2, 40, "forecast", 60, "'battery reserve >= 40%' "
                + "(reserve): the value moved back to 60.00", Clock.SECONDS, 0, "reserve")));
        t.properties(statuses(f, false));
        reserve = light(b, "reserve");
        assertEquals("green", reserve.get("light").asText());
        assertEquals("'battery reserve >= 40%' (reserve): the value moved back to 60.00",
                reserve.get("recovery").asText());
    }
}
