package dev.predmon.live;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Default robot names drop the part every log's name shares, cut between words and numbers. */
class RobotNamesTest {

    @Test
    void theDefaultDropsWhatAllNamesShare() {
        assertEquals(List.of("15_17", "16_02"), RobotNames.byFile().shown(List.of("monitor2022-10-11T15_17+02_00",
                "monitor2022-10-11T16_02+02_00")));
        assertEquals(List.of("11T15_17", "12T09_00"), RobotNames.byFile().shown(List.of(
                "monitor2022-10-11T15_17+02_00", "monitor2022-10-12T09_00+02_00")), "no number cut in two");
    }

    @Test
    void shortNamesAGivenPatternAndASingleLogStayWhole() {
        assertEquals(List.of("robot-1", "robot-2"), RobotNames.byFile().shown(List.of("robot-1", "robot-2")));
        List<String> longNames = List.of("monitor2022-10-11T15_17", "monitor2022-10-11T16_02");
        assertEquals(longNames, RobotNames.pattern("{file}").shown(longNames));
        assertEquals(List.of("monitor2022-10-11T15_17"), RobotNames.byFile().shown(longNames.subList(0, 1)));
    }
}
