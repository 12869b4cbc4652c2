#!/usr/bin/python3
"""The paired speed guard's decision (bench/paired/paired_verdict.py) on synthetic timing samples: no
timing is measured here. Its Mann-Whitney p-values are checked against scipy's, its verdicts on samples
whose answer is known by construction, and its exit status as the nightly reads it.
usage: paired_verdict_test.py REPOSITORY_ROOT"""
import json
import os
import random
import subprocess
import sys
import tempfile
import unittest

from scipy import stats

ROOT = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
SCRIPT = os.path.join(ROOT, "bench", "paired", "paired_verdict.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import paired_verdict  # noqa: E402


def noisy(rng, base, spread, count):
    """`count` timings around `base` seconds, each off by up to +-spread (relative), never below base / 2."""
    return [max(base * (1 + rng.uniform(-spread, spread)), base / 2) for _ in range(count)]


class MannWhitneyAgainstScipy(unittest.TestCase):
    def test_exact_without_ties(self):
        rng = random.Random(1)
        for n, m, shift in ((5, 5, 0.0), (7, 9, 0.05), (12, 12, -0.02), (20, 20, 0.01), (3, 11, 0.2)):
            before = [rng.random() for _ in range(n)]
            after = [rng.random() + shift for _ in range(m)]
            expected = stats.mannwhitneyu(after, before, alternative="greater", method="exact").pvalue
            self.assertAlmostEqual(paired_verdict.mann_whitney_greater(after, before), expected, places=12,
                                   msg=f"n={n} m={m} shift={shift}")

    def test_normal_approximation_with_ties_and_large_samples(self):
        rng = random.Random(2)
        for n, m, ticks in ((10, 10, 5), (21, 21, 40), (30, 25, 1000)):
            before = [rng.randrange(ticks) for _ in range(n)]
            after = [rng.randrange(ticks) + ticks // 10 for _ in range(m)]
            expected = stats.mannwhitneyu(after, before, alternative="greater", method="asymptotic",
                                          use_continuity=True).pvalue
            self.assertAlmostEqual(paired_verdict.mann_whitney_greater(after, before), expected, places=12,
                                   msg=f"n={n} m={m} ticks={ticks}")


class Verdicts(unittest.TestCase):
    def test_a_planted_slowdown_is_slower(self):
        rng = random.Random(3)
        before = noisy(rng, 0.050, 0.05, 21)
        after = [t * 1.3 for t in noisy(rng, 0.050, 0.05, 21)]
        result = paired_verdict.decide(before, after, cases=4)
        self.assertEqual(result["verdict"], "SLOWER", result)
        self.assertGreater(result["median_ratio"], 1.2)

    def test_the_same_program_is_not_slower(self):
        for seed in range(20):
            rng = random.Random(100 + seed)
            before = noisy(rng, 0.050, 0.10, 21)
            after = noisy(rng, 0.050, 0.10, 21)
            self.assertNotEqual(paired_verdict.decide(before, after, cases=4)["verdict"], "SLOWER", seed)

    def test_a_significant_but_tiny_slowdown_is_within_the_tolerance(self):
        # 1 % slower with almost no noise: the rank test is sure, the size is below min_effect.
        before = [0.050 + 1e-6 * k for k in range(21)]
        after = [t * 1.01 for t in before]
        result = paired_verdict.decide(before, after)
        self.assertLess(result["p_slower"], 1e-6)
        self.assertEqual(result["verdict"], "same", result)

    def test_noise_widens_the_tolerance(self):
        # Paired ratios spread evenly over 1.10 +-40 %: a 10 % shift is within the noise of this measurement,
        # whose quartiles lie 20 % either side of the median.
        rng = random.Random(4)
        before = noisy(rng, 0.050, 0.02, 21)
        spread = [1.10 * (1 + 0.4 * (k / 10 - 1)) for k in range(21)]
        rng.shuffle(spread)
        after = [t * r for t, r in zip(before, spread)]
        result = paired_verdict.decide(before, after)
        self.assertAlmostEqual(result["median_ratio"], 1.10, places=9)
        self.assertGreater(result["tolerance"], 0.2, result)
        self.assertNotEqual(result["verdict"], "SLOWER", result)

    def test_a_faster_build_is_faster(self):
        rng = random.Random(5)
        before = noisy(rng, 0.080, 0.05, 15)
        after = [t * 0.6 for t in noisy(rng, 0.080, 0.05, 15)]
        self.assertEqual(paired_verdict.decide(before, after)["verdict"], "faster")

    def test_bonferroni_over_cases(self):
        # A shift that is significant for one case alone but not at alpha / 40.
        before = [0.050, 0.051, 0.052, 0.053, 0.054, 0.055]
        after = [0.056, 0.057, 0.058, 0.059, 0.060, 0.061]
        self.assertEqual(paired_verdict.decide(before, after, cases=1)["verdict"], "SLOWER")
        self.assertEqual(paired_verdict.decide(before, after, cases=40)["verdict"], "same")

    def test_bad_samples_are_refused(self):
        with self.assertRaises(ValueError):
            paired_verdict.decide([0.05, 0.05], [0.05, 0.05])
        with self.assertRaises(ValueError):
            paired_verdict.decide([0.05] * 5, [0.05] * 4)
        with self.assertRaises(ValueError):
            paired_verdict.decide([0.05, 0.0, 0.05], [0.05] * 3)


class CommandLine(unittest.TestCase):
    def run_script(self, cases):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "samples.json")
            with open(path, "w") as stream:
                json.dump({"cases": cases}, stream)
            return subprocess.run(["/usr/bin/python3", SCRIPT, path], capture_output=True, text=True)

    def case(self, name, before, after):
        return {"case": name, "before": {"cpu_s": before, "wall_s": before},
                "after": {"cpu_s": after, "wall_s": after}}

    def test_exit_3_when_one_case_is_slower(self):
        rng = random.Random(6)
        same = noisy(rng, 0.05, 0.03, 15)
        slow = [t * 1.5 for t in same]
        result = self.run_script([self.case("ape", same, list(reversed(same))), self.case("map", same, slow)])
        self.assertEqual(result.returncode, 3, result.stdout + result.stderr)
        self.assertIn("map: SLOWER", result.stdout)
        self.assertIn("ape: same", result.stdout)

    def test_exit_0_when_no_case_is_slower(self):
        rng = random.Random(7)
        before = noisy(rng, 0.05, 0.03, 15)
        after = noisy(rng, 0.05, 0.03, 15)
        result = self.run_script([self.case("ape", before, after)])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)

    def test_exit_2_on_too_few_samples(self):
        result = self.run_script([self.case("ape", [0.05, 0.05], [0.06, 0.06])])
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)


if __name__ == "__main__":
    unittest.main()
