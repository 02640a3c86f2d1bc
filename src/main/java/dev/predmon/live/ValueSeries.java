package dev.predmon.live;

import java.util.ArrayList;
import java.util.List;

/**
 * The property's readings over one run (e.g. the battery level over time), in constant memory for a run of any
 * length: once {@code capacity} points are kept, every other one is dropped and from then on only every second
 * reading is kept (then every fourth, ...). The latest reading is always part of {@link #points()}, so the plot ends where the
 * value is now. A plot a few hundred pixels wide needs no more.
 */
final class ValueSeries {

    private final int capacity;
    private final double[] times;
    private final double[] values;
    private int size;
    private int stride = 1;
    private long offered;
    private double lastTime = Double.NaN;
    private double lastValue;
    private boolean lastKept;

    ValueSeries(int capacity) {
        if (capacity < 2 || capacity % 2 != 0) {
            throw new IllegalArgumentException("capacity must be even and at least 2, got " + capacity);
        }
        this.capacity = capacity;
        this.times = new double[capacity];
        this.values = new double[capacity];
    }

    void add(double time, double value) {
        lastTime = time;
        lastValue = value;
        lastKept = offered++ % stride == 0;
        if (!lastKept) {
            return;
        }
        if (size == capacity) {
            for (int i = 0; i < capacity / 2; i++) {
                times[i] = times[2 * i];
                values[i] = values[2 * i];
            }
            size = capacity / 2;
            stride *= 2;
            lastKept = (offered - 1) % stride == 0;
            if (!lastKept) {
                return;
            }
        }
        times[size] = time;
        values[size] = value;
        size++;
    }

    boolean isEmpty() {
        return Double.isNaN(lastTime);
    }

    /** The latest reading, or NaN before any. */
    double last() {
        return isEmpty() ? Double.NaN : lastValue;
    }

    /** {@code [time, value]} pairs in time order, the latest reading last; at most capacity + 1. */
    List<double[]> points() {
        List<double[]> out = new ArrayList<>(size + 1);
        for (int i = 0; i < size; i++) {
            out.add(new double[] {times[i], values[i]});
        }
        if (!isEmpty() && !lastKept) {
            out.add(new double[] {lastTime, lastValue});
        }
        return out;
    }

    void clear() {
        size = 0;
        stride = 1;
        offered = 0;
        lastTime = Double.NaN;
        lastKept = false;
    }
}
