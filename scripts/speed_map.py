#!/usr/bin/env python3
"""Walks every state of a gait-parameter grid and maps speed, falls and reward (EXPERIMENTS.md).

usage: scripts/speed_map.py --output DIR [--grid GRID] [--stop-time 60] [--jobs N]
                            [--set comp.var=value ...] [--system FILE] [--stride PATH]
                            [--compare V_TABLE.csv ...]

For each state of GRID (`name:min:max:step,...`, default the 455 states of Experiment 1) it runs
`stride run SYSTEM` (default models/experiments/evaluate-point.xml: gait + robot + learner in
evaluation mode) with `eval.eval_point` set to the state, into DIR/points/<values>/, N at a time.
Points already evaluated are kept, so an interrupted map continues where it stopped. Then it
writes DIR/speed_map.csv (grid values, W-footstep windows walked without a fall, falls, mean
speed over those windows in cm/s, mean reward per RL step as the learner sees it, falls included) and, for a 2-D grid, DIR/speed_map.png (gnuplot), and
prints the best states. This is the ground truth the learner's V(s) should rank alike: with
--compare, for each learner V table (v_table.csv or a snapshot, same grid) it prints the Spearman
rank correlation of V with the mean reward and how many of the 10 largest V are among the 10
fastest states without a fall.
Python 3 standard library and gnuplot only.
"""
import argparse
import concurrent.futures
import csv
import itertools
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXP1_GRID = "period_time:450:960:15,swing_right_left:15:39:2"


def parse_grid(text):
    dims = []
    for item in text.split(","):
        parts = item.split(":")
        if len(parts) != 4:
            sys.exit(f"--grid: '{item}' is not name:min:max:step")
        name = parts[0]
        try:
            lo, hi, step = (float(p) for p in parts[1:])
        except ValueError:
            sys.exit(f"--grid: '{item}': min, max and step must be numbers")
        if step <= 0 or hi < lo:
            sys.exit(f"--grid: '{item}': need step > 0 and max >= min")
        count = int(round((hi - lo) / step)) + 1
        dims.append((name, [lo + i * step for i in range(count)]))
    return dims


def fmt(v):
    return f"{v:g}"


def evaluate(args, values, folder):
    result = os.path.join(folder, "evaluation.csv")
    if os.path.isfile(result):
        return folder
    point = ",".join(fmt(v) for v in values)
    cmd = [args.stride, "run", args.system, "--quiet", "--no-plots", "--output", folder,
           "--stop-time", str(args.stop_time), "--set", f"eval.grid={args.grid}",
           "--set", f"eval.eval_point={point}"]
    for s in args.set:
        cmd += ["--set", s]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0 or not os.path.isfile(result):
        raise RuntimeError(f"point {point}: stride run failed ({done.returncode}):\n"
                           f"{done.stderr.strip()}")
    return folder


def read_point(folder, names):
    with open(os.path.join(folder, "evaluation.csv"), newline="") as f:
        row = next(csv.DictReader(f))
    rewards = []
    steps = os.path.join(folder, "steps.csv")
    with open(steps, newline="") as f:
        for r in csv.DictReader(f):
            rewards.append(float(r["reward"]))
    falls = int(row["falls"])
    walked = int(row["windows"]) - falls  # the evaluator counts a fall as a window
    return {
        "values": [float(row[n]) for n in names],
        "windows": walked,
        "falls": falls,
        "mean_speed": float(row["mean_speed"]) if walked > 0 else float("nan"),
        "mean_reward": sum(rewards) / len(rewards) if rewards else float("nan"),
    }


def plot(out_dir, names, rows):
    units = {"period_time": " (ms)", "swing_right_left": " (mm)"}
    dat = os.path.join(out_dir, "speed_map.dat")
    falls = os.path.join(out_dir, "speed_map_falls.dat")
    with open(dat, "w") as f, open(falls, "w") as g:
        previous = None
        for r in sorted(rows, key=lambda r: (r["values"][1], r["values"][0])):
            x, y = r["values"]
            if previous is not None and y != previous:
                f.write("\n")
            previous = y
            speed = r["mean_speed"] if r["windows"] > 0 else "NaN"
            f.write(f"{fmt(x)} {fmt(y)} {speed} {r['mean_reward']}\n")
            if r["falls"] > 0:
                g.write(f"{fmt(x)} {fmt(y)} {r['falls']}\n")
    best = max((r for r in rows if r["falls"] == 0 and r["windows"] > 0),
               key=lambda r: r["mean_speed"], default=None)
    script = os.path.join(out_dir, "speed_map.gp")
    x_label, y_label = (n + units.get(n, "") for n in names)
    mark = ""
    if best is not None:
        bx, by = (fmt(v) for v in best["values"])
        mark = (f", '-' using 1:2 with points pt 6 ps 3 lw 2 lc rgb 'white' "
                f"title 'fastest without falls: {bx}, {by}'")
    fall_plot = (f", '{falls}' using 1:2 with points pt 2 ps 0.5 lc rgb 'black' "
                 f"title 'fell at least once'") if os.path.getsize(falls) > 0 else ""
    with open(script, "w") as f:
        f.write("set terminal pngcairo size 1400,600 noenhanced font ',11'\n")
        f.write(f"set output '{os.path.join(out_dir, 'speed_map.png')}'\n")
        f.write("set multiplot layout 1,2\nset autoscale fix\nset key below\n")
        f.write(f"set xlabel '{x_label}'\nset ylabel '{y_label}'\n")
        f.write("set palette rgb 33,13,10\n")
        f.write("set title 'mean speed over the W-footstep windows (cm/s)'\n")
        f.write(f"plot '{dat}' using 1:2:3 with image notitle{fall_plot}{mark}\n")
        if best is not None:
            f.write(f"{bx} {by}\ne\n")
        f.write("set title 'mean reward per RL step (falls included)'\n")
        f.write(f"plot '{dat}' using 1:2:4 with image notitle{fall_plot}\n")
        f.write("unset multiplot\n")
    done = subprocess.run(["gnuplot", script], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"gnuplot failed on {script}: {done.stderr.strip()}")


def ranks(values):
    """Ranks 0..n-1, ties sharing their mean rank."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    out = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            out[order[k]] = (i + j) / 2
        i = j + 1
    return out


def spearman(a, b):
    ra, rb = ranks(a), ranks(b)
    ma, mb = sum(ra) / len(ra), sum(rb) / len(rb)
    cov = sum((x - ma) * (y - mb) for x, y in zip(ra, rb))
    var = (sum((x - ma) ** 2 for x in ra) * sum((y - mb) ** 2 for y in rb)) ** 0.5
    return cov / var if var > 0 else float("nan")


def compare(path, names, rows):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != names + ["V"]:
            sys.exit(f"{path}: expected the columns {','.join(names + ['V'])}")
        values = {tuple(float(r[n]) for n in names): float(r["V"]) for r in reader}
    by_state = {tuple(r["values"]): r for r in rows}
    if values.keys() != by_state.keys():
        sys.exit(f"{path}: another grid than the speed map")
    states = sorted(by_state)
    rho = spearman([values[s] for s in states], [by_state[s]["mean_reward"] for s in states])
    top_v = set(sorted(states, key=lambda s: -values[s])[:10])
    fastest = set(sorted((s for s in states if by_state[s]["falls"] == 0
                          and by_state[s]["windows"] > 0),
                         key=lambda s: -by_state[s]["mean_speed"])[:10])
    print(f"{path}: Spearman rho(V, mean reward) = {rho:.3f}; "
          f"{len(top_v & fastest)} of its 10 largest V are among the 10 fastest states "
          "without a fall")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", required=True, help="folder for the points and the map")
    parser.add_argument("--grid", default=EXP1_GRID, help="name:min:max:step,... (eval.grid)")
    parser.add_argument("--stop-time", type=float, default=60.0, help="simulated s per point")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="parallel runs")
    parser.add_argument("--set", action="append", default=[], help="comp.var=value for all")
    parser.add_argument("--system", default=os.path.join(ROOT, "models/experiments/"
                                                         "evaluate-point.xml"))
    parser.add_argument("--stride", default=os.path.join(ROOT, "build/bin/stride"))
    parser.add_argument("--compare", action="append", default=[], metavar="V_TABLE",
                        help="a learner V table of the same grid to rank against the map")
    args = parser.parse_args()
    if not os.access(args.stride, os.X_OK):
        sys.exit(f"{args.stride}: not found; build first (scripts/build.sh) or give --stride")
    if args.stop_time <= 0 or args.jobs < 1:
        sys.exit("--stop-time must be positive and --jobs at least 1")
    dims = parse_grid(args.grid)
    names = [n for n, _ in dims]
    states = list(itertools.product(*(v for _, v in dims)))
    os.makedirs(os.path.join(args.output, "points"), exist_ok=True)

    folders = [os.path.join(args.output, "points", "_".join(fmt(v) for v in s)) for s in states]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(evaluate, args, s, f) for s, f in zip(states, folders)]
        for done, fut in enumerate(concurrent.futures.as_completed(futures), start=1):
            try:
                fut.result()
            except RuntimeError as e:
                pool.shutdown(cancel_futures=True)
                sys.exit(str(e))
            print(f"\rspeed map: {done}/{len(states)} points", end="", file=sys.stderr)
    print(file=sys.stderr)

    rows = [read_point(f, names) for f in folders]
    table = os.path.join(args.output, "speed_map.csv")
    with open(table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(names + ["windows", "falls", "mean_speed", "mean_reward"])
        for r in rows:
            w.writerow([fmt(v) for v in r["values"]] +
                       [r["windows"], r["falls"], r["mean_speed"], r["mean_reward"]])
    if len(names) == 2:
        plot(args.output, names, rows)

    walked = [r for r in rows if r["windows"] > 0]
    print(f"{table}: {len(rows)} states, {sum(r['falls'] > 0 for r in rows)} fell at least once")
    for title, key, pool in (("fastest without falls", "mean_speed",
                              [r for r in walked if r["falls"] == 0]),
                             ("highest mean reward", "mean_reward", walked)):
        top = sorted(pool, key=lambda r: -r[key])[:5]
        print(f"{title}: " + "; ".join(
            "/".join(fmt(v) for v in r["values"]) + f" {r['mean_speed']:.2f} cm/s "
            f"({r['falls']} falls, reward {r['mean_reward']:.1f})" for r in top))
    for path in args.compare:
        compare(path, names, rows)


if __name__ == "__main__":
    main()
