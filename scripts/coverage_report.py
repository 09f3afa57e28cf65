#!/usr/bin/env python3
"""Per-folder coverage table, floor check and list of untested functions, from gcovr's JSON.

Reads gcovr's summary JSON (per-file line and branch counts) and its full JSON (per-function
call counts), writes summary.txt, summary.md and untested-functions.txt into OUT_DIR, prints the
table, and exits 1 when a folder is under its floor in FLOORS. Python 3 standard library only.

Usage: coverage_report.py --summary-json F --json F --build DIR [--floors F] --out-dir DIR
"""

import argparse
import json
import os
import subprocess
import sys
from collections import defaultdict

# top-level source folders in the order of CONTRIBUTING.md; components/ also gets one row each
FOLDERS = ["common", "fmi", "orchestrator", "components", "remote", "suite", "study",
           "calibration", "viewer", "cli"]


def folder_rows(files):
    """folder -> [line_covered, line_total, branch_covered, branch_total] for every row."""
    rows = defaultdict(lambda: [0, 0, 0, 0])
    for f in files:
        parts = f["filename"].split("/")
        keys = [parts[0] if parts[0] in FOLDERS else "other"]
        if parts[0] == "components" and len(parts) > 2:
            keys.append("components/" + parts[1])
        keys.append("total")
        for key in keys:
            row = rows[key]
            row[0] += f["line_covered"]
            row[1] += f["line_total"]
            row[2] += f["branch_covered"]
            row[3] += f["branch_total"]
    return rows


def ordered_keys(rows):
    keys = []
    for folder in FOLDERS:
        if folder in rows:
            keys.append(folder)
        if folder == "components":
            keys += sorted(k for k in rows if k.startswith("components/"))
    if "other" in rows:
        keys.append("other")
    keys.append("total")
    return keys


def percent(covered, total):
    return 100.0 * covered / total if total else 100.0


def table_text(rows, keys):
    header = "{:<26} {:>13} {:>7}   {:>13} {:>7}".format("folder", "lines", "%", "branches", "%")
    out = [header, "-" * len(header)]
    for key in keys:
        lc, lt, bc, bt = rows[key]
        name = key + ("/" if key not in ("total", "other") else "")
        out.append("{:<26} {:>13} {:>7.1f}   {:>13} {:>7.1f}".format(
            name, f"{lc}/{lt}", percent(lc, lt), f"{bc}/{bt}", percent(bc, bt)))
    return "\n".join(out) + "\n"


def table_markdown(rows, keys):
    out = ["| folder | lines | line % | branches | branch % |", "|---|---:|---:|---:|---:|"]
    for key in keys:
        lc, lt, bc, bt = rows[key]
        name = f"`{key}/`" if key not in ("total", "other") else f"**{key}**"
        out.append(f"| {name} | {lc}/{lt} | {percent(lc, lt):.1f} | {bc}/{bt} | "
                   f"{percent(bc, bt):.1f} |")
    return "\n".join(out) + "\n"


def read_floors(path):
    """folder -> (min line %, min branch %); '#' starts a comment."""
    floors = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.split("#", 1)[0].split()
            if not line:
                continue
            if len(line) != 3:
                sys.exit(f"{path}:{number}: expected 'folder min-line-% min-branch-%'")
            try:
                floors[line[0].rstrip("/")] = (float(line[1]), float(line[2]))
            except ValueError:
                sys.exit(f"{path}:{number}: the floors must be numbers")
    return floors


def parse_posix_nm(line):
    """(name, type) of one line of `nm --format=posix`, or None for a file header."""
    if line.endswith(":"):
        return None
    # NAME TYPE VALUE SIZE, or NAME TYPE VALUE, or NAME TYPE: the name may hold spaces
    for count in (3, 2, 1):
        fields = line.rsplit(" ", count)
        if len(fields) == count + 1 and len(fields[1]) == 1:
            return fields[0], fields[1]
    return None


def untested_functions(full_json, build):
    """folder -> [(file, line, name)] of the functions gcov saw never called that have external
    linkage. gcov names functions without their linkage; the objects' symbol tables have it (T
    and W are global definitions; statics and the anonymous namespace are t)."""
    external = set()
    objects = []
    for dirpath, _, filenames in os.walk(build):
        objects += [os.path.join(dirpath, n) for n in filenames if n.endswith(".o")]
    for start in range(0, len(objects), 200):
        out = subprocess.run(["nm", "-C", "--defined-only", "--extern-only", "--format=posix"]
                             + objects[start:start + 200], check=True, capture_output=True,
                             text=True).stdout
        for line in out.splitlines():
            parsed = parse_posix_nm(line)
            if parsed and parsed[1] in ("T", "W"):
                external.add(parsed[0])
    by_folder = defaultdict(list)
    for f in full_json["files"]:
        parts = f["file"].split("/")
        folder = parts[0] if parts[0] in FOLDERS else "other"
        if folder == "components" and len(parts) > 2:
            folder = "components/" + parts[1]
        counts = {l["line_number"]: l["count"] for l in f["lines"] if not l["gcovr/noncode"]}
        for fn in f["functions"]:
            # lambdas are no one's public interface
            if fn["execution_count"] != 0 or fn["name"] not in external or "{lambda(" in fn["name"]:
                continue
            # a call inlined into its caller does not count as a call of the function, but its
            # first line does (unless another function shares that line, as instantiations do)
            first = min((n for n in counts if n >= fn["lineno"]), default=None)
            if first is not None and counts[first] > 0:
                continue
            by_folder[folder].append((f["file"], fn["lineno"], fn["name"]))
    return by_folder


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--summary-json", required=True)
    parser.add_argument("--json", required=True)
    parser.add_argument("--build", required=True, help="the build tree with the object files")
    parser.add_argument("--floors", help="check the floors in this file (else only report)")
    parser.add_argument("--out-dir", required=True)
    args = parser.parse_args()

    with open(args.summary_json, encoding="utf-8") as f:
        summary = json.load(f)
    with open(args.json, encoding="utf-8") as f:
        full = json.load(f)

    rows = folder_rows(summary["files"])
    keys = ordered_keys(rows)
    text = table_text(rows, keys)
    with open(os.path.join(args.out_dir, "summary.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    with open(os.path.join(args.out_dir, "summary.md"), "w", encoding="utf-8") as f:
        f.write(table_markdown(rows, keys))
    print(text, end="")

    untested = untested_functions(full, args.build)
    count = sum(len(v) for v in untested.values())
    with open(os.path.join(args.out_dir, "untested-functions.txt"), "w", encoding="utf-8") as f:
        f.write(f"# {count} functions with external linkage that no test called, by folder\n")
        for key in [k for k in keys if k in untested]:
            f.write(f"\n## {key}/ ({len(untested[key])})\n")
            for path, lineno, name in sorted(untested[key]):
                f.write(f"{path}:{lineno}: {name}\n")
    print(f"\ncoverage: {count} untested functions with external linkage: "
          + ", ".join(f"{k}/ {len(untested[k])}" for k in keys if k in untested))

    failed = False
    floors = read_floors(args.floors) if args.floors else {}
    for folder, (min_line, min_branch) in floors.items():
        if folder not in rows:
            print(f"coverage: {args.floors} names {folder}/, which has no measured source",
                  file=sys.stderr)
            failed = True
            continue
        lc, lt, bc, bt = rows[folder]
        for what, measured, floor in (("lines", percent(lc, lt), min_line),
                                      ("branches", percent(bc, bt), min_branch)):
            if measured < floor:
                print(f"coverage: {folder}/ {what} {measured:.1f} % is under its floor "
                      f"{floor:.1f} % ({args.floors})", file=sys.stderr)
                failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
