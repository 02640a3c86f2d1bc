package dev.predmon.cli;

import org.junit.jupiter.api.Test;

class Nav2RunsProbeTest {
    @Test
    void probe() throws Exception {
        java.nio.file.Path m = Nav2Runs.models();
        java.nio.file.Path bag = java.nio.file.Files.createTempFile("run", ".mcap");
        Nav2Runs.write(bag, Nav2Runs.messages(dev.predmon.simulate.Scenario.DEPLETED, 11));
        Cli r = Cli.run("watch", "--no-follow", "--models", m.toString(), "--log", bag.toString());
        System.out.println("CODE " + r.code() + "\nOUT\n" + r.out() + "\nERR\n" + r.err());
    }
}
