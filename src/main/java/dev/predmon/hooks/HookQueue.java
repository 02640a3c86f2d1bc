package dev.predmon.hooks;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * The commands waiting to run, fair per log: each log has a queue of its own, bounded, and the runners take the logs
 * in turn, one command of each. A log whose alarm flaps fills only its own queue, so another log's first warning
 * always finds room and waits behind at most one command of each other log.
 *
 * <p>Within a log, commands run one at a time, in the order they were queued: a robot's recovery never runs before
 * (or beside) the warning it ends. At most {@code threads} commands run at once, each of another log; a runner
 * thread lives while there is something it may run.
 */
final class HookQueue {

    /** A queued command: run on a runner thread; {@link #dropped} when it will never run. */
    interface Job extends Runnable {
        /** Called instead of {@link #run} for a job still waiting when the queue is closed. */
        void dropped();
    }

    private final int threads;
    private final int perLog;
    /** The logs with something waiting, in turn order: the next command is the head of the first queue. */
    private final Map<String, ArrayDeque<Job>> waiting = new LinkedHashMap<>();
    private final Set<Thread> runners = new HashSet<>();
    /** The logs one of whose commands runs now: their next command waits for it. */
    private final Set<String> running = new HashSet<>();
    private boolean closed;

    HookQueue(int threads, int perLog) {
        this.threads = threads;
        this.perLog = perLog;
    }

    /** Queues {@code job} for {@code log}; false (nothing queued) when {@code log} has {@code perLog} waiting. */
    synchronized boolean offer(String log, Job job) {
        if (closed) {
            return false;
        }
        ArrayDeque<Job> q = waiting.computeIfAbsent(log, l -> new ArrayDeque<>());
        if (q.size() >= perLog) {
            return false;
        }
        q.add(job);
        if (runners.size() < threads) {
            Thread t = new Thread(this::runJobs, "predmon-hook-" + (runners.size() + 1));
            t.setDaemon(true);
            runners.add(t);
            t.start();
        }
        return true;
    }

    /** A job with its log. */
    private record Taken(String log, Job job) {
    }

    /**
     * The next job in turn of a log none of whose commands runs now, or null (the runner then ends; the runner of
     * the busy log takes its next command when its own ends). {@code done} is the log whose command just ended.
     */
    private synchronized Taken next(String done) {
        if (done != null) {
            running.remove(done);
        }
        Iterator<Map.Entry<String, ArrayDeque<Job>>> it = waiting.entrySet().iterator();
        while (it.hasNext()) {
            Map.Entry<String, ArrayDeque<Job>> e = it.next();
            if (running.contains(e.getKey())) {
                continue;
            }
            Job job = e.getValue().poll();
            it.remove();
            if (!e.getValue().isEmpty()) {
                waiting.put(e.getKey(), e.getValue()); // to the back of the turn
            }
            running.add(e.getKey());
            return new Taken(e.getKey(), job);
        }
        runners.remove(Thread.currentThread());
        notifyAll();
        return null;
    }

    private void runJobs() {
        for (Taken t = next(null); t != null; t = next(t.log())) {
            t.job().run();
        }
    }

    /**
     * Takes no more jobs and waits up to {@code millis} for the waiting and running ones to finish; then drops what
     * still waits and interrupts what still runs (a job ends its command when interrupted), waiting a little more.
     */
    void close(long millis) {
        List<Job> dropped = new ArrayList<>();
        synchronized (this) {
            closed = true;
            awaitRunners(millis);
            waiting.values().forEach(dropped::addAll);
            waiting.clear();
            runners.forEach(Thread::interrupt);
        }
        dropped.forEach(Job::dropped);
        synchronized (this) {
            awaitRunners(2000);
        }
    }

    /** Waits up to {@code millis} for every runner to end; holding the lock. */
    private void awaitRunners(long millis) {
        long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (!runners.isEmpty() && System.nanoTime() < until) {
            try {
                wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(until - System.nanoTime())));
            } catch (InterruptedException e) {
                // watch is being stopped: the close goes on; CommandHooks keeps the interrupt status
            }
        }
    }
}
