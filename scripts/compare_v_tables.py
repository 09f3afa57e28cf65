#!/usr/bin/env python3
"""Compares learnt V tables state by state: rank correlation, best states and best regions.

usage: scripts/compare_v_tables.py A B [B2 ...] [--top 10]

Each table is either Stride's CSV (header `period_time,swing_right_left,V`, one row per state)
or the study authors' `.dat` (`#` header lines, then whitespace-separated `swing period V`).
The tables are matched on (period_time, swing_right_left); they must hold the same states.
Prints A's best state and the bounding box of its `--top` largest-V states, then, as Markdown,
one row per B: the Spearman rank correlation of the two tables over all states (tied values
share their mean rank), the best state of each, how many of A's top states are among B's, and
each one's top box (period range × swing range). Equal V are ordered by state, so the top sets
do not depend on the row order. Errors (exit status 1) name the file and, where one is at fault,
the line or state. Python 3 standard library only.
"""
import argparse
import csv
import math
import os
import sys

PERIOD, SWING = "period_time", "swing_right_left"


def fail(message):
    sys.exit(message)  # prints to stderr, exit status 1


def number(text, path, line):
    try:
        value = float(text)
    except ValueError:
        fail(f"{path}:{line}: '{text}' is not a number")
    # nan would make every comparison false and so corrupt ranks silently
    if not math.isfinite(value):
        fail(f"{path}:{line}: '{text}' is not a finite number")
    return value


def add_state(table, path, line, period, swing, v):
    state = (period, swing)
    if state in table:
        fail(f"{path}:{line}: state {fmt_state(state)} appears twice")
    table[state] = v


def read_csv(path, lines):
    rows = list(csv.reader(lines))
    header = [name.strip() for name in rows[0]]
    if sorted(header[:-1]) != sorted([PERIOD, SWING]) or header[-1] != "V":
        fail(f"{path}:1: expected the header '{PERIOD},{SWING},V', got '{','.join(header)}'")
    # the grid columns are found by name, so either order of the two works
    ip, iswing = header.index(PERIOD), header.index(SWING)
    table = {}
    for line, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        if len(row) != 3:
            fail(f"{path}:{line}: expected 3 fields, got {len(row)}")
        add_state(table, path, line, number(row[ip], path, line),
                  number(row[iswing], path, line), number(row[2], path, line))
    return table


def read_dat(path, lines):
    table = {}
    for line, text in enumerate(lines, start=1):
        if not text.strip() or text.lstrip().startswith("#"):
            continue
        fields = text.split()
        if len(fields) != 3:
            fail(f"{path}:{line}: expected 'swing period V', got {len(fields)} fields")
        swing, period, v = (number(f, path, line) for f in fields)
        add_state(table, path, line, period, swing, v)
    return table


def is_dat(lines):
    """The authors' files open with '#' comments and separate by blanks; ours are CSV."""
    first = next((text for text in lines if text.strip()), "")
    return first.lstrip().startswith("#") or "," not in first


def read_table(path):
    """{(period_time, swing_right_left): V} of a table in either format."""
    try:
        # the authors' headers hold a non-ASCII 'ç' in an unknown encoding; only digits matter
        with open(path, encoding="utf-8", errors="replace", newline="") as f:
            lines = f.read().splitlines()
    except OSError as e:
        fail(f"{path}: cannot read: {e.strerror}")
    table = (read_dat if is_dat(lines) else read_csv)(path, lines)
    if not table:
        fail(f"{path}: no states")
    return table


def check_same_states(a_path, a, b_path, b):
    only_a = sorted(set(a) - set(b))
    if only_a:
        fail(f"{b_path}: has no state {fmt_state(only_a[0])} ({PERIOD}/{SWING}), which {a_path} "
             f"has ({len(only_a)} such states)")
    only_b = sorted(set(b) - set(a))
    if only_b:
        fail(f"{b_path}: state {fmt_state(only_b[0])} ({PERIOD}/{SWING}) is not in {a_path} "
             f"({len(only_b)} such states)")


def ranks(values):
    """Ranks 1..n of the values; a run of equal values shares the mean of its ranks."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    result = [0.0] * len(values)
    start = 0
    while start < len(order):
        end = start
        while end + 1 < len(order) and values[order[end + 1]] == values[order[start]]:
            end += 1
        for k in range(start, end + 1):
            result[order[k]] = (start + end) / 2 + 1
        start = end + 1
    return result


def pearson(x, y):
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    sxx = sum((a - mx) ** 2 for a in x)
    syy = sum((b - my) ** 2 for b in y)
    if sxx == 0 or syy == 0:
        return math.nan  # a constant table has no ranking to correlate
    return sxy / math.sqrt(sxx * syy)


def spearman(a, b):
    states = sorted(a)
    return pearson(ranks([a[s] for s in states]), ranks([b[s] for s in states]))


def top_states(table, count):
    return sorted(table, key=lambda s: (-table[s], s))[:count]


def box(states):
    periods = [p for p, _ in states]
    swings = [s for _, s in states]
    return f"{min(periods):g}..{max(periods):g} × {min(swings):g}..{max(swings):g}"


def fmt_state(state):
    return "/".join(f"{v:g}" for v in state)


def fmt_best(table, top):
    return f"{fmt_state(top[0])} ({table[top[0]]:.1f})"


def display_names(paths):
    """Base names, unless two of them clash (e.g. walk/dados/x.dat and walk2/dados/x.dat)."""
    names = [os.path.basename(p) for p in paths]
    return names if len(set(names)) == len(names) else list(paths)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        epilog="Formats: Stride CSV 'period_time,swing_right_left,V' or the authors' .dat "
               "('#' header, then 'swing period V'). Exit status 1 on malformed tables or "
               "differing state sets.")
    parser.add_argument("a", metavar="A", help="the reference V table")
    parser.add_argument("b", metavar="B", nargs="+", help="V tables compared against A")
    parser.add_argument("--top", type=int, default=10,
                        help="size of the best region of each table (default 10)")
    args = parser.parse_args()
    if args.top < 1:
        parser.error("--top must be at least 1")

    a = read_table(args.a)
    tables = []
    for path in args.b:
        b = read_table(path)
        check_same_states(args.a, a, path, b)
        tables.append(b)

    names = display_names([args.a, *args.b])
    top_a = top_states(a, args.top)
    print(f"A = {names[0]}: {len(a)} states ({PERIOD}/{SWING}); best {fmt_best(a, top_a)}; "
          f"top {len(top_a)} box {box(top_a)}")
    print()
    print(f"| B | Spearman ρ | best of A | best of B | A's top {len(top_a)} in B's | "
          f"top box of A ({PERIOD} × {SWING}) | top box of B |")
    print("|---|---|---|---|---|---|---|")
    for name, b in zip(names[1:], tables):
        top_b = top_states(b, args.top)
        rho = spearman(a, b)
        rho_text = "n/a" if math.isnan(rho) else f"{rho:.3f}"
        print(f"| {name} | {rho_text} | {fmt_best(a, top_a)} | {fmt_best(b, top_b)} | "
              f"{len(set(top_a) & set(top_b))} | {box(top_a)} | {box(top_b)} |")


if __name__ == "__main__":
    main()
