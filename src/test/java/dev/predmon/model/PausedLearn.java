package dev.predmon.model;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.Learning;

import java.nio.file.Path;

/**
 * A learn, as a separate process, that stops just before one step of writing the models and waits there to be
 * killed: {@code PausedLearn LOGS MODELS STEP}. It prints {@code paused before STEP} when it gets there, so that
 * {@link KilledLearnTest} can kill it at exactly that step.
 */
final class PausedLearn {

    private PausedLearn() {
    }

    public static void main(String[] args) throws Exception {
        Path logs = Path.of(args[0]);
        Path models = Path.of(args[1]);
        String pauseBefore = args[2];
        Abstraction abstraction = AbstractionFiles.defaults();
        Learning.learnAndWrite(logs, models, abstraction, l -> { }, step -> {
            if (step.equals(pauseBefore)) {
                System.out.println("paused before " + step);
                System.out.flush();
                while (true) {
                    try {
                        Thread.sleep(60_000);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                }
            }
        });
        System.out.println("finished without pausing: no step '" + pauseBefore + "'");
    }
}
