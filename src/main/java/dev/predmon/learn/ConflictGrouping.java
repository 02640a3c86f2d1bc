package dev.predmon.learn;

import dev.predmon.mealy.MealyTrace;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;

/**
 * Splits a scenario's samples into as few groups as it can such that no group holds a {@link Conflict}, so
 * that each group can be learned as one deterministic Mealy machine.
 *
 * <p>Runs of one scenario often disagree after identical inputs (the battery drains at different rates), and
 * a single Mealy machine cannot hold both answers: LearnLib rejects the second sample with an
 * {@code IllegalArgumentException} without a message. Conflicts are pairwise (a prefix tree is consistent iff
 * no two of its samples disagree after a common input prefix), so the minimum split is a colouring of the
 * conflict graph. Colouring optimally is NP-hard; this uses DSatur (Brélaz 1979), which is optimal on
 * bipartite graphs and close elsewhere, with ties broken by sample order so the result is deterministic.
 */
public final class ConflictGrouping {

    /**
     * The split.
     *
     * @param groups the samples of each group, in input order
     * @param splits for each group after the first, one conflict that kept its first sample out of the earlier groups
     */
    public record Result(List<List<MealyTrace>> groups, List<Conflict> splits) {
    }

    private ConflictGrouping() {
    }

    /** Groups {@code samples} (which should be in a deterministic order, e.g. by file name). */
    public static Result group(List<MealyTrace> samples) {
        int n = samples.size();
        Conflict[][] conflict = new Conflict[n][];
        BitSet[] adjacent = new BitSet[n];
        for (int i = 0; i < n; i++) {
            adjacent[i] = new BitSet(n);
            conflict[i] = new Conflict[n];
        }
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                Conflict c = Conflict.between(samples.get(i), samples.get(j));
                if (c != null) {
                    adjacent[i].set(j);
                    adjacent[j].set(i);
                    conflict[i][j] = c;
                    conflict[j][i] = c;
                }
            }
        }
        int[] colour = new int[n];
        Arrays.fill(colour, -1);
        BitSet[] neighbourColours = new BitSet[n];
        for (int i = 0; i < n; i++) {
            neighbourColours[i] = new BitSet();
        }
        List<Conflict> splits = new ArrayList<>();
        int colours = 0;
        for (int step = 0; step < n; step++) {
            int pick = -1;
            for (int v = 0; v < n; v++) {
                if (colour[v] >= 0) {
                    continue;
                }
                if (pick < 0 || saturationThenDegree(v, pick, neighbourColours, adjacent) > 0) {
                    pick = v;
                }
            }
            int c = neighbourColours[pick].nextClearBit(0);
            if (c == colours) {
                colours++;
                if (c > 0) {
                    splits.add(blocking(pick, colour, adjacent[pick], conflict));
                }
            }
            colour[pick] = c;
            for (int w = adjacent[pick].nextSetBit(0); w >= 0; w = adjacent[pick].nextSetBit(w + 1)) {
                neighbourColours[w].set(c);
            }
        }
        List<List<MealyTrace>> groups = new ArrayList<>();
        for (int c = 0; c < colours; c++) {
            groups.add(new ArrayList<>());
        }
        for (int i = 0; i < n; i++) {
            groups.get(colour[i]).add(samples.get(i));
        }
        return new Result(groups.stream().map(List::copyOf).toList(), List.copyOf(splits));
    }

    /** Positive when {@code v} should be coloured before {@code w}: higher saturation, then higher degree. */
    private static int saturationThenDegree(int v, int w, BitSet[] neighbourColours, BitSet[] adjacent) {
        int bySaturation = Integer.compare(neighbourColours[v].cardinality(), neighbourColours[w].cardinality());
        return bySaturation != 0 ? bySaturation : Integer.compare(adjacent[v].cardinality(), adjacent[w].cardinality());
    }

    /** A conflict between {@code v} and an already coloured sample: the reason it needs a new group. */
    private static Conflict blocking(int v, int[] colour, BitSet neighbours, Conflict[][] conflict) {
        for (int w = neighbours.nextSetBit(0); w >= 0; w = neighbours.nextSetBit(w + 1)) {
            if (colour[w] >= 0) {
                return conflict[v][w];
            }
        }
        throw new IllegalStateException("a new group was opened without a conflict");
    }
}
