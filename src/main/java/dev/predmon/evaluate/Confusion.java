package dev.predmon.evaluate;

import java.util.List;

/**
 * Actual (the scenario's label) against predicted (a warning in time) over every test run. A faulty run
 * counts as predicted faulty only when warned strictly before its violation; a faulty run without violation
 * is left out ({@code unscored}), since there is nothing to predict in time.
 *
 * @param truePositives  faulty runs warned before the violation
 * @param falseNegatives faulty runs missed (late warnings included)
 * @param falsePositives nominal runs with a warning
 * @param trueNegatives  nominal runs without a warning
 * @param unscored       faulty runs whose log ends before the violation
 */
public record Confusion(int truePositives, int falseNegatives, int falsePositives, int trueNegatives, int unscored) {

    public static Confusion of(List<RunResult> runs) {
        int tp = 0;
        int fn = 0;
        int fp = 0;
        int tn = 0;
        int un = 0;
        for (RunResult r : runs) {
            switch (r.verdict()) {
                case WARNED_BEFORE_VIOLATION -> tp++;
                case MISSED, WARNED_LATE -> fn++;
                case FALSE_ALARM -> fp++;
                case QUIET -> tn++;
                case WARNED_NO_VIOLATION, QUIET_NO_VIOLATION -> un++;
            }
        }
        return new Confusion(tp, fn, fp, tn, un);
    }

    /** Hits over faulty runs with a violation, or null without any. */
    public Double recall() {
        return truePositives + falseNegatives == 0 ? null : (double) truePositives / (truePositives + falseNegatives);
    }

    /** False alarms over nominal runs, or null without any. */
    public Double falseAlarmRate() {
        return falsePositives + trueNegatives == 0 ? null : (double) falsePositives / (falsePositives + trueNegatives);
    }
}
