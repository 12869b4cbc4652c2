#!/usr/bin/python3
"""bench/cli/cli_table.py: the "met" column and the --check exit status decide whether a nightly
performance job fails, so a missed target must read NO and exit 3, and a met one must not.

The inputs are hand-written hyperfine exports with known medians (the figures below, not measured ones):
the test checks the table logic, never how fast anything runs.
Usage: cli_table_test.py REPOSITORY_ROOT
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
TABLE = os.path.join(ROOT, "bench", "cli", "cli_table.py")


def write_case(out_dir, name, target_ms, target_mb, programs):
    """programs: label -> (median ms, peak RSS MB, exit status)."""
    with open(os.path.join(out_dir, "cases.txt"), "a") as handle:
        handle.write(f"{name}|{target_ms}|{target_mb}|args of {name}\n")
    results = []
    for label, (median_ms, rss_mb, status) in programs.items():
        seconds = median_ms / 1000.0
        results.append({"command": label, "median": seconds, "min": seconds, "max": seconds,
                        "user": seconds * 0.9, "system": seconds * 0.1})
        with open(os.path.join(out_dir, f"{name}.{label}.rss_kb"), "w") as handle:
            handle.write(str(int(rss_mb * 1024)))
        with open(os.path.join(out_dir, f"{name}.{label}.status"), "w") as handle:
            handle.write(str(status))
    with open(os.path.join(out_dir, f"{name}.json"), "w") as handle:
        json.dump({"results": results}, handle)


def run_table(out_dir, labels, check):
    command = ["/usr/bin/python3", TABLE] + (["--check"] if check else []) + [out_dir, "5", "a note"] + labels
    return subprocess.run(command, capture_output=True, text=True)


def met_column(stdout):
    rows = [line for line in stdout.splitlines() if line.startswith("| `")]
    return {row.split("|")[1].strip().strip("`"): row.split("|")[-2].strip() for row in rows}


class CliTableTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.out = self.directory.name

    def tearDown(self):
        self.directory.cleanup()

    def test_every_target_met_reads_yes_and_exits_0_under_check(self):
        write_case(self.out, "fast", "10", "15", {"after": (9.9, 14.9, 0)})
        write_case(self.out, "no-target", "-", "-", {"after": (500.0, 900.0, 0)})
        result = run_table(self.out, ["after"], check=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(met_column(result.stdout), {"fast": "yes", "no-target": "-"})
        with open(os.path.join(self.out, "summary.json")) as handle:
            summary = json.load(handle)
        self.assertEqual([case["met"] for case in summary["cases"]], [True, None])

    def test_a_slow_case_a_fat_case_and_a_failing_program_each_read_no(self):
        write_case(self.out, "slow", "60", "-", {"after": (60.5, 40.0, 0)})
        write_case(self.out, "fat", "10", "15", {"after": (2.0, 15.5, 0)})
        write_case(self.out, "crashed", "10", "15", {"after": (1.0, 5.0, 2)})
        write_case(self.out, "fine", "50", "-", {"after": (49.0, 30.0, 0)})
        result = run_table(self.out, ["after"], check=True)
        self.assertEqual(result.returncode, 3, result.stdout + result.stderr)
        self.assertEqual(met_column(result.stdout), {"slow": "NO", "fat": "NO", "crashed": "NO", "fine": "yes"})
        self.assertIn("slow, fat, crashed", result.stderr)
        self.assertIn("1.0 (exit 2)", result.stdout)

    def test_without_check_a_miss_is_reported_but_the_exit_status_is_0(self):
        write_case(self.out, "slow", "60", "-", {"after": (75.0, 40.0, 0)})
        result = run_table(self.out, ["after"], check=False)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(met_column(result.stdout), {"slow": "NO"})

    def test_half_compares_the_last_program_with_the_first(self):
        write_case(self.out, "worker-halved", "half", "-", {"before": (258.0, 110.0, 0), "after": (128.0, 54.0, 0)})
        write_case(self.out, "worker-not-halved", "half", "-", {"before": (258.0, 110.0, 0), "after": (130.0, 54.0, 0)})
        result = run_table(self.out, ["before", "after"], check=True)
        self.assertEqual(result.returncode, 3)
        self.assertEqual(met_column(result.stdout), {"worker-halved": "yes", "worker-not-halved": "NO"})

    def test_half_with_one_program_uses_the_recorded_before(self):
        write_case(self.out, "worker-fast", "half:255.8", "-", {"after": (127.0, 54.0, 0)})
        write_case(self.out, "worker-slow", "half:255.8", "-", {"after": (128.5, 54.0, 0)})
        result = run_table(self.out, ["after"], check=True)
        self.assertEqual(result.returncode, 3)
        self.assertEqual(met_column(result.stdout), {"worker-fast": "yes", "worker-slow": "NO"})
        self.assertIn("1/2 of the recorded before (255.8 ms)", result.stdout)

    def test_a_second_program_outranks_the_recorded_before(self):
        write_case(self.out, "worker", "half:255.8", "-", {"before": (300.0, 110.0, 0), "after": (140.0, 54.0, 0)})
        result = run_table(self.out, ["before", "after"], check=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(met_column(result.stdout), {"worker": "yes"})

    def test_half_without_a_recorded_before_and_one_program_is_said_to_be_unchecked(self):
        write_case(self.out, "worker", "half", "-", {"after": (500.0, 54.0, 0)})
        result = run_table(self.out, ["after"], check=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(met_column(result.stdout), {"worker": "-"})
        self.assertIn("not checked: one program", result.stdout)


if __name__ == "__main__":
    unittest.main()
