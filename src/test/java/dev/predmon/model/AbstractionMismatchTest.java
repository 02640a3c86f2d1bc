package dev.predmon.model;

import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Where two abstractions differ is named only where it matters to the models: a property's action never does. */
class AbstractionMismatchTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static List<String> places(String a, String b) throws Exception {
        List<String> out = new ArrayList<>();
        AbstractionMismatch.diff(JSON.readTree(a), JSON.readTree(b), "", out);
        return out;
    }

    @Test
    void aPropertysActionIsNoDifference() throws Exception {
        String learned = "{\"locations\":{\"charging_station\":[1,2]},\"properties\":["
                + "{\"name\":\"battery\",\"action\":\"plug it in\"},{\"name\":\"grasp\",\"action\":\"stop\"}]}";
        String inUse = "{\"locations\":{\"dock\":[1,2]},\"properties\":["
                + "{\"name\":\"battery\",\"action\":\"call someone\"},{\"name\":\"grasp\"}]}";
        assertEquals(List.of("locations.charging_station", "locations.dock"), places(learned, inUse));
    }

    @Test
    void aPropertysOtherFieldsStillDiffer() throws Exception {
        String learned = "{\"properties\":[{\"name\":\"battery\",\"below\":20}],\"safety\":{\"action\":\"a\"}}";
        String inUse = "{\"properties\":[{\"name\":\"battery\",\"below\":25}],\"safety\":{\"action\":\"b\"}}";
        assertEquals(List.of("properties[0].below"), places(learned, inUse));
    }
}
