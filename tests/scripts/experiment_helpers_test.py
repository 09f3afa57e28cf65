#!/usr/bin/env python3
"""Tests of scripts/speed_map.py (a caller of `stride sweep`), scripts/seed_spread.py (against the
built `stride` CLI) and scripts/compare_v_tables.py."""
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
COMPARE = os.path.join(SOURCE, "scripts", "compare_v_tables.py")


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
            # 20 s: 17 complete windows of W = 4 footsteps (0.912 s each) after the start
            self.assertEqual(int(fast["windows"]), 17)
            # a deterministic measurement of the plant (to update after a deliberate model
            # change, read mean_speed from this speed_map.csv): pinned to 0.2 %
            self.assertAlmostEqual(float(fast["mean_speed"]), 15.232, delta=0.03)
            # the map's figures follow from the point's own windows (steps.csv): the mean speed
            # is the distance over the measured time, the mean reward the mean of the paper's
            # reward 0.33 10^(v/10) (docs/learner.md) over the windows
            steps = read_rows(os.path.join(out, "points", "450_15", "steps.csv"))
            self.assertEqual(len(steps), 17)
            distance = sum(float(r["distance"]) for r in steps)
            duration = sum(float(r["duration"]) for r in steps)
            self.assertAlmostEqual(float(fast["mean_speed"]), 100 * distance / duration, places=9)
            rewards = [0.33 * 10 ** (float(r["speed"]) / 10) for r in steps]
            self.assertAlmostEqual(float(fast["mean_reward"]), sum(rewards) / len(rewards),
                                   places=9)
            self.assertGreater(int(slow["falls"]), 0)
            self.assertLess(float(slow["mean_reward"]), 0)
            self.assertIn("fastest without falls: 450/15", done.stdout)
            with open(os.path.join(out, "speed_map.png"), "rb") as png:
                head = png.read(24)
            self.assertEqual(head[:8], b"\x89PNG\r\n\x1a\n")
            self.assertEqual(head[12:16], b"IHDR")
            self.assertEqual((int.from_bytes(head[16:20], "big"),
                              int.from_bytes(head[20:24], "big")), (1400, 600))

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
            # a parameter the system does not have: stride sweep's own message comes through
            wrong = run(SPEED_MAP, "--stride", CLI, "--output", out, "--stop-time", "1",
                        "--grid", "period_time:600:600:1,swing_right_left:20:20:1",
                        "--set", "gait.no_such_variable=1")
            self.assertNotEqual(wrong.returncode, 0)
            self.assertIn("point 600,20 cannot run", wrong.stderr)
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


def write_dat(path, values):
    """A V table in the study authors' format: '#' header, then 'swing period V'."""
    with open(path, "w") as f:
        f.write("#Passos_total= 6\n\n#p2_value p1_value Qvalue2p \n")
        # swing-major, as the authors write it: another row order than the CSV's
        for (p, s), v in sorted(values.items(), key=lambda kv: (kv[0][1], kv[0][0])):
            f.write(f"{s} {p}  {v:g}\n")


class compare_v_tables(unittest.TestCase):
    GRID = [(p, s) for p in (450, 465, 480) for s in (15, 17)]
    # distinct values: best 465/17, then 450/17; the top-2 box is 450..465 × 17..17
    A = dict(zip(GRID, (1.0, 5.0, 3.0, 6.0, 2.0, 4.0)))

    def test_rank_correlation_best_states_and_overlap(self):
        with tempfile.TemporaryDirectory() as tmp:
            a = os.path.join(tmp, "a.csv")
            with open(a, "w") as f:
                f.write("period_time,swing_right_left,V\n")
                for (p, s), v in self.A.items():
                    f.write(f"{p},{s},{v}\n")
            same = os.path.join(tmp, "same.dat")  # a monotone transform: the same ranking
            write_dat(same, {k: v ** 3 + 10 for k, v in self.A.items()})
            reversed_ = os.path.join(tmp, "reversed.dat")
            write_dat(reversed_, {k: -v for k, v in self.A.items()})
            # the two best states tie: mean ranks 5.5, rho = 17 / sqrt(17.5 * 17) = 0.986, and
            # the smaller state comes first among equal V
            tied = os.path.join(tmp, "tied.dat")
            write_dat(tied, {k: 9.0 if v >= 5 else v for k, v in self.A.items()})
            done = run(COMPARE, "--top", "2", a, same, reversed_, tied)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertIn("A = a.csv: 6 states (period_time/swing_right_left); best 465/17 (6.0); "
                          "top 2 box 450..465 × 17..17", done.stdout)
            self.assertIn("| same.dat | 1.000 | 465/17 (6.0) | 465/17 (226.0) | 2 | "
                          "450..465 × 17..17 | 450..465 × 17..17 |", done.stdout)
            self.assertIn("| reversed.dat | -1.000 | 465/17 (6.0) | 450/15 (-1.0) | 0 | "
                          "450..465 × 17..17 | 450..480 × 15..15 |", done.stdout)
            self.assertIn("| tied.dat | 0.986 | 465/17 (6.0) | 450/17 (9.0) | 2 |", done.stdout)

    def test_other_states_and_malformed_tables_are_errors(self):
        with tempfile.TemporaryDirectory() as tmp:
            a = os.path.join(tmp, "a.dat")
            write_dat(a, self.A)
            fewer = os.path.join(tmp, "fewer.dat")
            write_dat(fewer, {k: v for k, v in self.A.items() if k != (480, 17)})
            other = run(COMPARE, a, fewer)
            self.assertEqual(other.returncode, 1)
            self.assertIn("fewer.dat: has no state 480/17", other.stderr)
            bad = os.path.join(tmp, "bad.csv")
            with open(bad, "w") as f:
                f.write("period_time,swing_right_left,V\n450,15,1\n450,17\n")
            malformed = run(COMPARE, a, bad)
            self.assertEqual(malformed.returncode, 1)
            self.assertIn("bad.csv:3: expected 3 fields", malformed.stderr)


if __name__ == "__main__":
    unittest.main()
