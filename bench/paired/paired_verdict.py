#!/usr/bin/python3
"""Decides from repeated paired timings whether a build is slower than the one before it.

A case is SLOWER when both hold:
  - significance: a one-sided Mann-Whitney U test says the after-times are larger than the before-times,
    p < alpha / cases (Bonferroni over the cases of one comparison). Exact U distribution without ties
    and n, m <= 20; otherwise the normal approximation with tie and continuity correction.
  - size: the median of the paired ratios after_i / before_i (each pair run back to back, so the ratio
    cancels the machine's drift) exceeds 1 + tolerance, where tolerance is the larger of min_effect and
    the noise of this very measurement: half the interquartile range of the paired ratios. A noisy
    machine thus widens the tolerance itself; no threshold comes from another machine.
A case that fails either is "same" (or "faster" when the mirrored test and size say so).

usage: paired_verdict.py SAMPLES.json [--alpha A] [--min-effect E] [--metric cpu|wall]
SAMPLES.json: {"cases": [{"case": NAME, "before": {"cpu_s": [...], "wall_s": [...]}, "after": {...}}, ...]}
Prints one line per case and writes nothing; exit 3 when a case is SLOWER, 0 otherwise, 2 bad input.
"""
import argparse
import json
import math
import statistics
import sys


def rank_sum_u(first, second):
    """U statistic of `first` (count of pairs first > second, ties counting one half) and the tie groups."""
    pooled = sorted([(value, 0) for value in first] + [(value, 1) for value in second])
    ranks = [0.0] * len(pooled)
    ties = []
    i = 0
    while i < len(pooled):
        j = i
        while j + 1 < len(pooled) and pooled[j + 1][0] == pooled[i][0]:
            j += 1
        for k in range(i, j + 1):
            ranks[k] = (i + j) / 2 + 1
        if j > i:
            ties.append(j - i + 1)
        i = j + 1
    rank_sum = sum(rank for rank, (_, group) in zip(ranks, pooled) if group == 0)
    n = len(first)
    return rank_sum - n * (n + 1) / 2, ties


def exact_upper_tail(u, n, m):
    """P(U >= u) under the null hypothesis, from the count of rank arrangements (no ties)."""
    # counts[k] = arrangements of n "first" among n + m values whose U equals k, built up one value at a time
    counts = [[0] * (n * m + 1) for _ in range(n + 1)]
    counts[0][0] = 1
    for total in range(1, n + m + 1):
        for taken in range(min(total, n), 0, -1):
            # the newest (largest) value is a "first": it beats the total - taken "second" values before it
            beaten = total - taken
            row, previous = counts[taken], counts[taken - 1]
            for k in range(n * m, beaten - 1, -1):
                row[k] += previous[k - beaten]
    arrangements = math.comb(n + m, n)
    at_least = sum(counts[n][math.ceil(u - 1e-9):])
    return at_least / arrangements


def mann_whitney_greater(first, second):
    """One-sided p-value that `first` tends to be larger than `second`."""
    n, m = len(first), len(second)
    if n == 0 or m == 0:
        raise ValueError("Mann-Whitney U needs samples on both sides")
    u, ties = rank_sum_u(first, second)
    if not ties and n <= 20 and m <= 20:
        return exact_upper_tail(u, n, m)
    total = n + m
    tie_term = sum(t ** 3 - t for t in ties) / (total * (total - 1))
    variance = n * m / 12 * ((total + 1) - tie_term)
    if variance == 0:
        return 1.0
    z = (u - n * m / 2 - 0.5) / math.sqrt(variance)
    return 0.5 * math.erfc(z / math.sqrt(2))


def quartiles(values):
    ordered = sorted(values)
    if len(ordered) < 2:
        return ordered[0], ordered[0]
    q = statistics.quantiles(ordered, n=4, method="inclusive")
    return q[0], q[2]


def decide(before, after, alpha=0.01, min_effect=0.02, cases=1):
    """The verdict of one case from paired samples (before[i] and after[i] ran back to back)."""
    if len(before) != len(after) or len(before) < 3:
        raise ValueError(f"need at least 3 paired samples, got {len(before)} before and {len(after)} after")
    if min(before) <= 0 or min(after) <= 0:
        raise ValueError("timings must be positive")
    ratios = [a / b for a, b in zip(after, before)]
    median_ratio = statistics.median(ratios)
    low, high = quartiles(ratios)
    tolerance = max(min_effect, (high - low) / 2)
    threshold = alpha / cases
    p_slower = mann_whitney_greater(after, before)
    p_faster = mann_whitney_greater(before, after)
    if p_slower < threshold and median_ratio > 1 + tolerance:
        verdict = "SLOWER"
    elif p_faster < threshold and median_ratio < 1 - tolerance:
        verdict = "faster"
    else:
        verdict = "same"
    return {
        "verdict": verdict,
        "runs": len(ratios),
        "median_before": statistics.median(before),
        "median_after": statistics.median(after),
        "median_ratio": median_ratio,
        "ratio_quartiles": [low, high],
        "tolerance": tolerance,
        "p_slower": p_slower,
        "p_faster": p_faster,
        "alpha_per_case": threshold,
    }


def decide_all(samples, metric="cpu", alpha=0.01, min_effect=0.02):
    key = f"{metric}_s"
    cases = samples["cases"]
    return [dict(case=case["case"], **decide(case["before"][key], case["after"][key], alpha, min_effect, len(cases)))
            for case in cases]


def describe(result):
    return (f"{result['case']}: {result['verdict']} - median {result['median_before'] * 1e3:.1f} -> "
            f"{result['median_after'] * 1e3:.1f} ms, paired ratio {result['median_ratio']:.3f} "
            f"(quartiles {result['ratio_quartiles'][0]:.3f}-{result['ratio_quartiles'][1]:.3f}, tolerance "
            f"{result['tolerance']:.3f}), one-sided Mann-Whitney p = {result['p_slower']:.2g} "
            f"(alpha per case {result['alpha_per_case']:.2g}), {result['runs']} pairs")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("samples")
    parser.add_argument("--alpha", type=float, default=0.01)
    parser.add_argument("--min-effect", type=float, default=0.02)
    parser.add_argument("--metric", choices=("cpu", "wall"), default="cpu")
    args = parser.parse_args()
    try:
        with open(args.samples) as stream:
            results = decide_all(json.load(stream), args.metric, args.alpha, args.min_effect)
    except (OSError, ValueError, KeyError) as error:
        print(f"paired_verdict.py: {args.samples}: {error}", file=sys.stderr)
        return 2
    for result in results:
        print(describe(result))
    return 3 if any(result["verdict"] == "SLOWER" for result in results) else 0


if __name__ == "__main__":
    sys.exit(main())
