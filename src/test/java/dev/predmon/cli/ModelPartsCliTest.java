package dev.predmon.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The parts of a model directory must be of one learn and agree with each other: {@code forecast.json} and the DOT
 * files carry the learn id of {@code index.json}, and the forecast's values fit the models and the abstraction.
 * Each directory here was accepted silently before (a forecast of another learn moved warnings by hundreds of
 * lines); each is now exit 3 with one line naming the file and what disagrees, and no verdict.
 */
class ModelPartsCliTest {

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    @TempDir
    Path tmp;
    Path models;

    @BeforeEach
    void copyShippedModels() throws IOException {
        models = ModelFilesCliTest.copyOfShippedModels(tmp);
    }

    private void refused(Path file, String what) {
        ModelFilesCliTest.refused(models, file, what);
    }

    private ObjectNode read(String name) throws IOException {
        return (ObjectNode) JSON.readTree(models.resolve(name).toFile());
    }

    private void write(String name, ObjectNode root) throws IOException {
        Files.writeString(models.resolve(name), JSON.writeValueAsString(root));
    }

    private ObjectNode forecast() throws IOException {
        return read("forecast.json");
    }

    private void write(ObjectNode forecast) throws IOException {
        write("forecast.json", forecast);
    }

    /** Models learned from 4 of the 10 sample runs per scenario: another learn over the same abstraction. */
    private Path anotherLearn() throws IOException {
        Path logs = tmp.resolve("logs");
        for (String scenario : new String[] {"direct", "recharge", "depleted"}) {
            Path dir = Files.createDirectories(logs.resolve(scenario));
            Path samples = Path.of("sample-logs", scenario);
            Files.copy(samples.resolve("scenario.json"), dir.resolve("scenario.json"));
            for (int seed = 1; seed <= 4; seed++) {
                Files.copy(samples.resolve(scenario + "-" + seed + ".log"), dir.resolve(scenario + "-" + seed + ".log"));
            }
        }
        Path other = tmp.resolve("other");
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", other.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        return other;
    }

    @Test
    void aForecastOfAnotherLearn() throws IOException {
        Files.copy(anotherLearn().resolve("forecast.json"), models.resolve("forecast.json"),
                StandardCopyOption.REPLACE_EXISTING);
        refused(models.resolve("forecast.json"), "learned with other models than the index lists");
    }

    /**
     * The other learn's index with its DOT files (its direct.dot and depleted.dot are the shipped ones byte for byte):
     * a consistent set of machines, but the forecast beside them is of the shipped learn.
     */
    @Test
    void anIndexAndMachinesOfAnotherLearnBesideTheShippedForecast() throws IOException {
        Path other = anotherLearn();
        Files.copy(other.resolve("index.json"), models.resolve("index.json"), StandardCopyOption.REPLACE_EXISTING);
        Files.copy(other.resolve("recharge.dot"), models.resolve("recharge.dot"));
        refused(models.resolve("forecast.json"), "learned with other models than the index lists");
    }

    /** A machine whose behaviour was changed by hand, its states and alphabet kept: nothing else would tell. */
    @Test
    void aDotFileChangedKeepingItsStatesAndAlphabet() throws IOException {
        Path dot = models.resolve("direct.dot");
        String text = Files.readString(dot);
        assertTrue(text.contains("[label=\"Delta / o_level_high\"]"), text);
        Files.writeString(dot, text.replaceFirst("Delta / o_level_high", "Delta / o_level_medium_six"));
        refused(models.resolve("index.json"), "its DOT files are not the ones it was written with");
    }

    @Test
    void anIndexWithoutALearnId() throws IOException {
        ObjectNode index = read("index.json");
        index.remove("learnId");
        write("index.json", index);
        refused(models.resolve("index.json"), "has no learn id");
    }

    @Test
    void aForecastWithoutALearnId() throws IOException {
        ObjectNode f = forecast();
        f.remove("learnId");
        write(f);
        refused(models.resolve("forecast.json"), "it has no learn id");
    }

    /** The first floor's entry, under {@code properties} as every property's. */
    private static ObjectNode battery(ObjectNode forecast) {
        return (ObjectNode) forecast.get("properties").get("battery");
    }

    @Test
    void aThresholdThatIsNotAProbability() throws IOException {
        for (double threshold : new double[] {2.0, -1.0}) {
            ObjectNode f = forecast();
            battery(f).put("threshold", threshold);
            write(f);
            refused(models.resolve("forecast.json"), "'properties.battery.threshold': " + threshold
                    + " is not a probability (from 0 to 1)");
        }
        ObjectNode f = forecast();
        battery(f).putNull("threshold");
        write(f);
        refused(models.resolve("forecast.json"), "'properties.battery.threshold': null is not a probability");
    }

    @Test
    void negativeRuns() throws IOException {
        ObjectNode f = forecast();
        f.put("runs", -5);
        write(f);
        refused(models.resolve("forecast.json"), "'runs': -5, expected 0 or more");
        f.put("runs", 31);
        write(f);
        refused(models.resolve("forecast.json"), "'runs': 31, but the first floor 'battery' counts 30 training runs");
        f.put("runs", 30);
        battery(f).put("runs", -5);
        write(f);
        refused(models.resolve("forecast.json"), "'properties.battery.runs': -5, expected 0 or more");
        battery(f).put("runs", 30).put("violating", 31);
        write(f);
        refused(models.resolve("forecast.json"), "'properties.battery.violating': 31 of 30 runs");
    }

    @Test
    void aBoundOtherThanTheAbstractions() throws IOException {
        ObjectNode f = forecast();
        battery(f).put("limit", 200.0);
        write(f);
        refused(models.resolve("forecast.json"), "'properties.battery.limit': 200.0 is not the property's floor (20.0)");
    }

    /** Keys of format 1 at the top of a file of format 2 would be ignored: refused. */
    @Test
    void aKeyOfFormat1AtTheTopOfFormat2() throws IOException {
        ObjectNode f = forecast();
        f.put("threshold", 0.5);
        write(f);
        refused(models.resolve("forecast.json"), "'threshold': not a key of format 2, where each property's forecast "
                + "is under 'properties'");
        f = forecast();
        f.put("format", 3);
        write(f);
        refused(models.resolve("forecast.json"), "'format': 3, expected 1 or 2");
    }

    @Test
    void aStateTheMachineDoesNotHave() throws IOException {
        ObjectNode f = forecast();
        ObjectNode direct = (ObjectNode) battery(f).get("states").get("direct");
        direct.set("99", direct.get("0").deepCopy());
        write(f);
        refused(models.resolve("forecast.json"), "'properties.battery.states': state 99 of machine 'direct' is not in "
                + "its DOT file (states 0 to 6)");
    }

    @Test
    void aMachineTheIndexDoesNotList() throws IOException {
        ObjectNode shipped = forecast();
        ObjectNode f = shipped.deepCopy();
        ObjectNode states = (ObjectNode) battery(f).get("states");
        states.set("ghost", states.remove("direct"));
        write(f);
        refused(models.resolve("forecast.json"), "'properties.battery.states': machine 'ghost' is not one index.json "
                + "lists");
    }

    /** learn refuses such names; read from an index they would reach a hook's environment and the terminal raw. */
    @Test
    void scenarioNamesWithControlCharacters() throws IOException {
        for (String name : new String[] {"direct\u001b[2J", "direct\u202egnp.exe", "-direct", ""}) {
            ObjectNode index = read("index.json");
            ((ObjectNode) index.withArray("scenarios").get(1)).put("name", name);
            write("index.json", index);
            String line = ModelFilesCliTest.refused(models, models.resolve("index.json"), "is not one learn writes");
            assertFalse(line.contains("\u001b") || line.contains("\u202e"), "shown escaped: " + line);
        }
    }

    /** Past the limits of every predmon file: one line with where, not an internal error. */
    @Test
    void aForecastNestedFiveThousandLevelsDeep() throws IOException {
        Files.writeString(models.resolve("forecast.json"),
                "{\"format\": 1, \"x\": " + "[".repeat(5_000) + "]".repeat(5_000) + "}");
        refused(models.resolve("forecast.json"), "line 1: not JSON: nested more than 64 levels deep");
    }

    @Test
    void aForecastWithA1500DigitNumber() throws IOException {
        String text = Files.readString(models.resolve("forecast.json"));
        Files.writeString(models.resolve("forecast.json"), text.replaceFirst("\"runs\" : 30,", "\"runs\" : "
                + "9".repeat(1_500) + ","));
        refused(models.resolve("forecast.json"), "line 5: not JSON: a number longer than 1000 digits");
    }
}
