package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.Forecast;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.parse.LogRecord;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The monitor decides when an alarm is over, and follows the recommended action (the shipped models). */
class AlarmTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    private static List<MonitorEvent> watch(Records r) throws Exception {
        ModelSet models = ModelStore.read(Path.of("models"), A);
        List<MonitorEvent> events = new ArrayList<>();
        PredictiveMonitor m = new PredictiveMonitor(models, A, 0, events::add);
        for (LogRecord record : r.list()) {
            m.accept(record);
        }
        return events;
    }

    @Test
    void aViolationThatHoldsAgainIsRecoveredAndTheForecastStartsOver() throws Exception {
        Records r = new Records();
        double[] levels = {30, 25, 21, 19.5, 18, 22, 40, 60, 80};
        for (int i = 0; i < levels.length; i++) {
            r.at(i * 10).level(levels[i]);
        }
        List<MonitorEvent> events = watch(r);
        List<String> kinds = events.stream().filter(e -> !(e instanceof MonitorEvent.ForecastChanged))
                .map(e -> e.getClass().getSimpleName()).toList();
        int violation = kinds.indexOf("Violation");
        int recovered = kinds.indexOf("Recovered");
        assertTrue(violation >= 0 && recovered > violation, "violated, then recovered: " + kinds);
        MonitorEvent.Recovered rec = (MonitorEvent.Recovered) events.stream()
                .filter(e -> e instanceof MonitorEvent.Recovered).findFirst().orElseThrow();
        assertEquals("property", rec.cause());
        assertEquals(22.0, rec.value(), 1e-9, "at the first reading at or above the bound");
        Forecast last = events.stream().filter(e -> e instanceof MonitorEvent.ForecastChanged)
                .map(e -> ((MonitorEvent.ForecastChanged) e).forecast()).reduce((a, b) -> b).orElseThrow();
        assertNotEquals(Forecast.Basis.VIOLATED, last.basis(), "the forecast starts over: " + last);
        assertTrue(last.probability() < 1.0, "no longer certain: " + last);
    }

    @Test
    void aGoToTheChargingStationIsTheActionUnderWayUntilTheRobotIsSentElsewhere() throws Exception {
        Records r = new Records().at(1).level(50).goTo("charging_station").at(5).level(45).goTo("kitchen");
        List<MonitorEvent.UnderWay> under = watch(r).stream().filter(e -> e instanceof MonitorEvent.UnderWay)
                .map(e -> (MonitorEvent.UnderWay) e).toList();
        assertEquals(2, under.size(), under.toString());
        assertTrue(under.get(0).underWay());
        assertEquals("goTo charging_station", under.get(0).by());
        assertEquals(1.0, under.get(0).time(), 0.01);
        assertEquals(false, under.get(1).underWay(), "sent elsewhere: " + under.get(1));
    }

    @Test
    void anAlarmStillUpWhenItsRunEndsEndsWithTheRun() throws Exception {
        // violated at 15, then a silence of 90 s: a new run begins; the violation's alarm ends with its run
        Records r = new Records().at(0).level(50).at(10).level(15).at(100).level(80);
        List<MonitorEvent> events = watch(r);
        // (the charger's deadline, owed since the low reading, passed in the silence: violated there, and ended too)
        List<String> kinds = events.stream().filter(e -> !(e instanceof MonitorEvent.Violation v)
                        || v.property().equals("battery")).filter(e -> !(e instanceof MonitorEvent.Recovered x)
                        || x.property().equals("battery")).map(e -> e.getClass().getSimpleName())
                .filter(List.of("Violation", "Recovered", "RunStarted", "Warning")::contains).toList();
        assertEquals(List.of("Violation", "Recovered", "RunStarted"), kinds, events.toString());
        MonitorEvent.Recovered rec = (MonitorEvent.Recovered) events.stream()
                .filter(e -> e instanceof MonitorEvent.Recovered x && x.property().equals("battery")).findFirst()
                .orElseThrow();
        assertEquals("run-ended", rec.cause());
        assertEquals(0, rec.run(), "the run that ended");
        assertEquals(r.list().get(4).line(), rec.line(), "at the record that began the next run");
        assertEquals("battery", rec.property());
    }
}
