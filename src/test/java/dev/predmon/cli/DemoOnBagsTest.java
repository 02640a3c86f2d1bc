package dev.predmon.cli;

import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.BagSink;
import dev.predmon.rosbag.Bags;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code demo --format mcap}: the demo's runs recorded as nav2 records them, as MCAP files growing chunk by chunk,
 * watched with {@code nav2} models; learned first from simulated recordings when there are none, or from the
 * recordings {@code simulate --format mcap} wrote.
 */
class DemoOnBagsTest {

    @TempDir
    Path tmp;

    private static List<BagMessage> read(Path bag) throws Exception {
        List<BagMessage> messages = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        Bags.read(bag, new BagSink() {
            @Override
            public void message(BagMessage message) {
                messages.add(message);
            }

            @Override
            public void problem(String line) {
                problems.add(line);
            }
        });
        assertEquals(List.of(), problems, bag.toString());
        return messages;
    }

    @Test
    void theDemoRunsOnRecordingsAndLearnsNav2ModelsFirst() throws Exception {
        Path models = tmp.resolve("models-nav2");
        Path work = tmp.resolve("work");
        Cli r = Cli.run("demo", "--format", "mcap", "--seconds", "1.5", "--work", work.toString(), "--models",
                models.toString());
        assertEquals(ExitCodes.OK, r.code(), r.out() + r.err());
        String out = r.out();
        assertTrue(out.contains("learning them with nav2 from 4 simulated runs of each scenario"), out);
        int warning = out.indexOf("WARNING");
        int violation = out.indexOf("VIOLATION of 'battery at least 20%'");
        assertTrue(warning > 0 && violation > warning, out);
        assertTrue(out.matches("(?s).*predicted [0-9.]+ s ahead: warning at battery [0-9.]+%, violation at [0-9.]+%.*"),
                out);
        assertTrue(out.contains("run ended with no warning and no violation"), out);
        assertTrue(Files.readString(models.resolve("abstraction.json")).contains("\"nav2\""));
        // What was watched is a complete recording of nav2's topics, end records and all.
        List<BagMessage> recorded = read(work.resolve("depleted-9001.mcap"));
        assertTrue(recorded.size() > 100, "messages: " + recorded.size());
        assertTrue(recorded.stream().anyMatch(m -> m.topic().equals("/dock_robot/_action/status")));
    }

    @Test
    void theDemoLearnsFromSimulatedRecordingsAndRefusesModelsThatMapNoTopic() {
        Path bags = tmp.resolve("bags");
        for (String s : List.of("direct", "recharge", "depleted")) {
            Cli sim = Cli.run("simulate", "--scenario", s, "--format", "mcap", "--runs", "3", "--out-dir",
                    bags.resolve(s).toString());
            assertEquals(ExitCodes.OK, sim.code(), sim.err());
        }
        Path models = tmp.resolve("m");
        Cli r = Cli.run("demo", "--format", "mcap", "--seconds", "1", "--work", tmp.resolve("w").toString(),
                "--models", models.toString(), "--logs", bags.toString());
        assertTrue(r.out().contains("learning them with nav2 from " + bags), r.out());
        assertEquals(ExitCodes.OK, r.code(), r.out() + r.err());

        Cli yarpModels = Cli.run("demo", "--format", "mcap", "--seconds", "1", "--work", tmp.resolve("w2").toString(),
                "--models", "models");
        assertEquals(ExitCodes.USAGE, yarpModels.code(), yarpModels.out() + yarpModels.err());
        assertTrue(yarpModels.err().contains("maps no ROS 2 topic"), yarpModels.err());
    }
}
