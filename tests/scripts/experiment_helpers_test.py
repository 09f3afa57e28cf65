#!/usr/bin/env python3
"""Tests of scripts/speed_map.py and scripts/seed_spread.py against the built `stride` CLI."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

SOURCE = os.environ["STRIDE_SOURCE_DIR"]
CLI = os.environ["STRIDE_CLI"]
SPEED_MAP = os.path.join(SOURCE, "scripts", "speed_map.py")
SEED_SPREAD = os.path.join(SOURCE, "scripts", "seed_spread.py")


def run(*args):
    return subprocess.run([sys.executable, *args], capture_output=True, text=True)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


class speed_map(unittest.TestCase):
    def test_walks_every_state_and_keeps_finished_points(self):
        with tempfile.TemporaryDirectory() as out:
            # two corners of Experiment 1's grid: the fast short period walks, 960 ms falls
            args = (SPEED_MAP, "--stride", CLI, "--output", out, "--jobs", "2",
                    "--stop-time", "20", "--grid", "period_time:450:960:510,swing_right_left:15:15:2")
            done = run(*args)
            self.assertEqual(done.returncode, 0, done.stderr)
            rows = read_rows(os.path.join(out, "speed_map.csv"))
            self.assertEqual([(r["period_time"], r["swing_right_left"]) for r in rows],
                             [("450", "15"), ("960", "15")])
            fast, slow = rows
            self.assertEqual(int(fast["falls"]), 0)
            self.assertGreater(int(fast["windows"]), 5)
            self.assertTrue(8 < float(fast["mean_speed"]) < 30, fast["mean_speed"])
            # with no falls, the mean reward is K1 10^(speed/K2) of the windows' speeds: positive
            self.assertGreater(float(fast["mean_reward"]), 0)
            self.assertGreater(int(slow["falls"]), 0)
            self.assertLess(float(slow["mean_reward"]), 0)
            self.assertIn("fastest without falls: 450/15", done.stdout)
            self.assertTrue(os.path.getsize(os.path.join(out, "speed_map.png")) > 1000)

            # a second call reuses the evaluated points (an interrupted map continues)
            result = os.path.join(out, "points", "450_15", "evaluation.csv")
            stamp = os.stat(result).st_mtime_ns
            again = run(*args)
            self.assertEqual(again.returncode, 0, again.stderr)
            self.assertEqual(os.stat(result).st_mtime_ns, stamp)
            self.assertEqual(read_rows(os.path.join(out, "speed_map.csv")), rows)

            # a learner table that ranks the two states as the map does, and one of another grid
            table = os.path.join(out, "v_table.csv")
            with open(table, "w") as f:
                f.write("period_time,swing_right_left,V\n450,15,10\n960,15,-5\n")
            ranked = run(*args, "--compare", table)
            self.assertEqual(ranked.returncode, 0, ranked.stderr)
            self.assertIn("Spearman rho(V, mean reward) = 1.000; 1 of its 10 largest V are among "
                          "the 10 fastest states without a fall", ranked.stdout)
            with open(table, "w") as f:
                f.write("period_time,swing_right_left,V\n450,15,10\n")
            other = run(*args, "--compare", table)
            self.assertNotEqual(other.returncode, 0)
            self.assertIn("another grid than the speed map", other.stderr)

    def test_bad_arguments_are_errors_naming_the_culprit(self):
        with tempfile.TemporaryDirectory() as out:
            bad = run(SPEED_MAP, "--stride", CLI, "--output", out, "--grid", "period_time:450:960")
            self.assertNotEqual(bad.returncode, 0)
            self.assertIn("'period_time:450:960' is not name:min:max:step", bad.stderr)
            missing = run(SPEED_MAP, "--stride", os.path.join(out, "nothing"), "--output", out)
            self.assertNotEqual(missing.returncode, 0)
            self.assertIn("not found", missing.stderr)
            # a parameter the system does not have: stride's own message comes through
            wrong = run(SPEED_MAP, "--stride", CLI, "--output", out, "--stop-time", "1",
                        "--grid", "period_time:600:600:1,swing_right_left:20:20:1",
                        "--set", "gait.no_such_variable=1")
            self.assertNotEqual(wrong.returncode, 0)
            self.assertIn("point 600,20: stride run failed", wrong.stderr)
            self.assertIn("no_such_variable", wrong.stderr)


def write_table(folder, values):
    os.makedirs(folder)
    with open(os.path.join(folder, "v_table.csv"), "w") as f:
        f.write("period_time,swing_right_left,V\n")
        for (p, s), v in values.items():
            f.write(f"{p},{s},{v}\n")


class seed_spread(unittest.TestCase):
    def test_best_states_and_the_states_most_runs_agree_on(self):
        with tempfile.TemporaryDirectory() as tmp:
            grid = [(p, s) for p in (450, 465, 480) for s in (15, 17)]
            a = {k: 0.0 for k in grid}
            b = {k: 0.0 for k in grid}
            a[(450, 15)], a[(465, 15)] = 90.0, 80.0
            b[(450, 15)], b[(480, 17)] = 70.0, 95.0
            write_table(os.path.join(tmp, "run-a"), a)
            write_table(os.path.join(tmp, "run-b"), b)
            done = run(SEED_SPREAD, "--top", "2", os.path.join(tmp, "run-a"),
                       os.path.join(tmp, "run-b"))
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertIn("| run-a | 450/15 | 90.0 | 450..465 × 15..15 |", done.stdout)
            self.assertIn("| run-b | 480/17 | 95.0 | 450..480 × 15..17 |", done.stdout)
            # 450/15 is in both top-2 sets: mean 80, sd of (90, 70) = 14.1
            self.assertIn("| 450/15 | 2 / 2 | 80.0 | 14.1 |", done.stdout)

    def test_other_grids_and_missing_tables_are_errors(self):
        with tempfile.TemporaryDirectory() as tmp:
            write_table(os.path.join(tmp, "a"), {(450, 15): 1.0, (465, 15): 2.0})
            write_table(os.path.join(tmp, "b"), {(450, 15): 1.0})
            other = run(SEED_SPREAD, os.path.join(tmp, "a"), os.path.join(tmp, "b"))
            self.assertNotEqual(other.returncode, 0)
            self.assertIn("another grid", other.stderr)
            missing = run(SEED_SPREAD, os.path.join(tmp, "c"))
            self.assertNotEqual(missing.returncode, 0)
            self.assertIn("missing", missing.stderr)


if __name__ == "__main__":
    unittest.main()
