package dev.predmon.monitor;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A look for new logs runs beside the following thread: starting one returns at once however long the look takes,
 * its result is taken only once it is done, and a look that failed says why where it is taken.
 */
class RescanTest {

    @Test
    @Timeout(10)
    void aSlowLookDoesNotHoldUpTheThreadThatStartedIt() throws Exception {
        CountDownLatch listed = new CountDownLatch(1);
        Rescan.Found found = new Rescan.Found(List.of(Path.of("robot-1.log")), List.of(Path.of(".")));
        try (Rescan rescan = new Rescan(() -> {
            try {
                listed.await(); // a directory of 10,000 logs on a busy machine
            } catch (InterruptedException e) {
                throw new IOException(e);
            }
            return found;
        })) {
            long start = System.nanoTime();
            rescan.start();
            rescan.start(); // one look at a time
            assertTrue(rescan.running());
            assertNull(rescan.take());
            assertTrue(System.nanoTime() - start < 1_000_000_000L);
            listed.countDown();
            Rescan.Found taken = null;
            while (taken == null) {
                Thread.sleep(1);
                taken = rescan.take();
            }
            assertEquals(found, taken);
            assertFalse(rescan.running());
            assertNull(rescan.take());
        }
    }

    @Test
    @Timeout(10)
    void aLookThatFailedSaysWhyWhereItIsTaken() throws Exception {
        try (Rescan rescan = new Rescan(() -> {
            throw new NoSuchFileException("logs");
        })) {
            rescan.start();
            IOException failed = null;
            while (failed == null) {
                Thread.sleep(1);
                try {
                    assertNull(rescan.take());
                } catch (IOException e) {
                    failed = e;
                }
            }
            assertEquals("logs", failed.getMessage());
            assertFalse(rescan.running());
        }
    }
}
