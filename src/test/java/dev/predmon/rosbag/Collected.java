package dev.predmon.rosbag;

import java.util.ArrayList;
import java.util.List;

/** A sink that keeps what a reader delivers, for tests. */
class Collected implements BagSink {

    final List<BagMessage> messages = new ArrayList<>();
    final List<String> problems = new ArrayList<>();

    @Override
    public void message(BagMessage message) {
        messages.add(message);
    }

    @Override
    public void problem(String line) {
        problems.add(line);
    }

    static Collected read(java.nio.file.Path path) throws java.io.IOException {
        Collected c = new Collected();
        Bags.read(path, c);
        return c;
    }
}
