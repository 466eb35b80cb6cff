#!/usr/bin/env python3
"""bench/public_sets.py: how many standard checks `sfcv check` decides on the public exports of
issue 45 (VerifAPS PPU/xPPU scenarios, AGRAFE instances), and which engine decided each.

    SFCV_PUBLIC_SETS=DIR bench/public_sets.py [--sfcv BIN] [--timeout T] [--only SUBDIR,...]
                                              [--limit-per-set N] [--files F,...] [--tsv]

Runs `sfcv check FILE --json --timeout T` (default checks, engine auto) on every .xml and
.grafcet file below DIR, one after the other, and prints a Markdown table (or TSV): per file the
the exit status, the checks decided (holds or violated), unknown, not checked, n/a, the engines
that decided them, and the wall time; then the totals, with decided % = decided / (checks -
n/a). A file sfcv refuses (exit 2) is a row with status "refused"; a run that prints no JSON
report is marked "no report" and listed after the totals (its checks cannot be counted). Downloads nothing: DIR is a folder the user
fetched (the same variable tests/io/public_sets_test.cpp reads). Each run is also bounded by an
outer `timeout` of 2 T + 30 s so that a run past its budget is reported as "killed", never hangs.
"""

import argparse
import collections
import json
import os
import subprocess
import sys
import time

DECIDED = ("holds", "violated")
EXIT_STATUS = {0: "holds", 1: "violated", 2: "refused", 3: "unknown", 4: "error"}


def find_files(root, only, limit):
    files = []
    for sub in sorted(os.listdir(root)):
        path = os.path.join(root, sub)
        if not os.path.isdir(path) or (only and sub not in only):
            continue
        here = []
        for dirpath, _, names in os.walk(path):
            for n in names:
                if n.endswith(".xml") or n.endswith(".grafcet"):
                    here.append(os.path.join(dirpath, n))
        here.sort()
        files.extend(here[:limit] if limit else here)
    return files


def run_one(sfcv, path, timeout):
    cmd = [sfcv, "check", path, "--json", "--timeout", str(timeout)]
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=2 * timeout + 30)
    except subprocess.TimeoutExpired:
        return {"status": "killed", "wall": time.monotonic() - start}
    wall = time.monotonic() - start
    row = {"status": EXIT_STATUS.get(p.returncode, f"exit {p.returncode}"), "wall": wall}
    try:
        doc = json.loads(p.stdout)
    except ValueError:
        # No report at all: a refused file (exit 2), or a run that printed nothing.
        if p.returncode != 2:
            row["status"] += ", no report"
        return row
    counts = collections.Counter()
    engines = collections.Counter()
    for prop in doc.get("properties", []):
        if prop.get("kind") != "standard-check":
            continue
        verdict = prop.get("verdict", "")
        if verdict in DECIDED:
            counts["decided"] += 1
            engines[prop.get("decided_by") or "?"] += 1
        elif verdict == "n/a":
            counts["n/a"] += 1
        elif verdict == "unknown":
            counts["unknown"] += 1
        else:
            counts["not checked"] += 1
    row.update(counts=counts, engines=engines)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--sfcv", default=os.environ.get(
        "SFCV", os.path.join(here, "..", "build", "ci", "sfcv")))
    ap.add_argument("--timeout", type=float, default=30)
    ap.add_argument("--only", default="", help="comma-separated subfolders (e.g. PPU,agrafe)")
    ap.add_argument("--limit-per-set", type=int, default=0, help="first N files of each subfolder")
    ap.add_argument("--files", default="", help="comma-separated files instead of the folder walk")
    ap.add_argument("--tsv", action="store_true")
    args = ap.parse_args()

    if args.files:
        files = args.files.split(",")
        root = os.path.commonpath(files) if len(files) > 1 else os.path.dirname(files[0])
    else:
        root = os.environ.get("SFCV_PUBLIC_SETS", "")
        if not root or not os.path.isdir(root):
            print("bench/public_sets.py: set SFCV_PUBLIC_SETS to the folder of fetched exports",
                  file=sys.stderr)
            return 2
        only = set(s for s in args.only.split(",") if s)
        files = find_files(root, only, args.limit_per_set)
    timeout = int(args.timeout) if args.timeout == int(args.timeout) else args.timeout

    cols = ["file", "status", "decided", "unknown", "not checked", "n/a", "engines", "wall s"]
    if args.tsv:
        print("\t".join(cols))
    else:
        print("| " + " | ".join(cols) + " |")
        print("|" + "---|" * len(cols))
    total = collections.Counter()
    total_engines = collections.Counter()
    statuses = collections.Counter()
    no_report = []
    per_set = collections.defaultdict(collections.Counter)
    for f in files:
        row = run_one(args.sfcv, f, timeout)
        statuses[row["status"]] += 1
        if "counts" not in row and row["status"] != "refused":
            no_report.append(os.path.relpath(f, root))
        c = row.get("counts", collections.Counter())
        e = row.get("engines", collections.Counter())
        total.update(c)
        total_engines.update(e)
        per_set[os.path.relpath(f, root).split(os.sep)[0]].update(c)
        eng = " ".join(f"{k}:{v}" for k, v in sorted(e.items()))
        cells = [os.path.relpath(f, root), row["status"], str(c["decided"]), str(c["unknown"]),
                 str(c["not checked"]), str(c["n/a"]), eng, f"{row['wall']:.1f}"]
        print(("\t" if args.tsv else " | ").join(cells) if args.tsv else
              "| " + " | ".join(cells) + " |", flush=True)
    applicable = total["decided"] + total["unknown"] + total["not checked"]
    pct = 100.0 * total["decided"] / applicable if applicable else 0.0
    eng = " ".join(f"{k}:{v}" for k, v in sorted(total_engines.items()))
    st = " ".join(f"{k}:{v}" for k, v in sorted(statuses.items()))
    summary = [f"total ({len(files)} files)", st, str(total["decided"]), str(total["unknown"]),
               str(total["not checked"]), str(total["n/a"]), eng, ""]
    print("\t".join(summary) if args.tsv else "| " + " | ".join(summary) + " |")
    print(f"\ndecided {total['decided']} of {applicable} applicable checks: {pct:.1f} % "
          f"(timeout {timeout} s, {args.sfcv})")
    for name, c in sorted(per_set.items()):
        n = c["decided"] + c["unknown"] + c["not checked"]
        print(f"  {name}: decided {c['decided']} of {n}"
              + (f" ({100.0 * c['decided'] / n:.1f} %)" if n else ""))
    if no_report:
        print(f"{len(no_report)} runs printed no report (their checks are not counted): "
              + ", ".join(no_report))
    return 0


if __name__ == "__main__":
    sys.exit(main())
