#!/usr/bin/env python3
"""The table of docs/reliability.md, "Every limit in every subcommand" (issue 52): each
subcommand (and engine) x {large chart, wide inputs, deep expressions} x {time, memory, states},
run under one limit at a time, with the outcome (held: exit 0/1 decided in time; exit 3: the
limit reached, what was decided printed; exit 2: a located error), the wall and CPU (user +
system) seconds and the peak resident memory of the run.

    bench/limits/limits_table.py build/release/sfcv [--jobs 2] > table.md

The inputs are written the way tests/e2e/limits_every_subcommand_test.cpp writes them.
"""
import argparse
import concurrent.futures
import os
import resource
import subprocess
import sys
import tempfile
import time

TIMEOUT = "2"
MEMORY = "300M"
STATES = "1000"
# Under the memory and states limits a run also gets a time limit, so that the table ends.
SAFETY = "20"


def write(dir_, name, text):
    path = os.path.join(dir_, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def inputs(dir_):
    n = 100000
    chain = ["PROGRAM Chain\n  VAR_INPUT a : BOOL; END_VAR\n  VAR_OUTPUT o : BOOL; END_VAR\n"
             "  INITIAL_STEP S0:\n  END_STEP\n"]
    for i in range(1, n):
        chain.append("  STEP S%d:\n%s  END_STEP\n" % (i, "    o(N);\n" if i == n - 1 else ""))
    for i in range(n):
        chain.append("  TRANSITION FROM S%d TO S%d := a;\n  END_TRANSITION\n" % (i, (i + 1) % n))
    chain.append("END_PROGRAM\n")
    large = write(dir_, "large.st", "".join(chain))
    large_csv = write(dir_, "large.csv", "a\n" + "1\n" * 5000)

    names = ["i%d" % i for i in range(200)]
    g7 = "".join("input %s;\n" % x for x in names)
    g7 += ("output o;\ngrafcet G {\n  step 1 initial;\n  step 2;\n  action 2: o;\n"
           "  transition t1: 1 -> 2 when %s;\n  transition t2: 2 -> 1 when %s;\n}\n"
           % (" & ".join(names[:100]), " & ".join(names[100:])))
    wide = write(dir_, "wide.g7", g7)
    wide_csv = write(dir_, "wide.csv", ",".join(names) + "\n" + (",".join("0" * 200) + "\n") * 1000)

    conj = " AND ".join(["a"] * 100000)
    nested = "a"
    for i in range(150):
        nested = "(" + nested + (" OR b)" if i % 2 else " AND NOT b)")
    deep = write(dir_, "deep.st",
                 "PROGRAM Deep\n  VAR_INPUT a : BOOL; b : BOOL; END_VAR\n"
                 "  VAR_OUTPUT o : BOOL; p : BOOL; END_VAR\n  o := %s;\n  p := %s;\nEND_PROGRAM\n"
                 % (conj, nested))
    deep_csv = write(dir_, "deep.csv", "a,b\n" + "1,0\n" * 1000)
    return [("large chart", large, large_csv, True), ("wide inputs", wide, wide_csv, False),
            ("deep expressions", deep, deep_csv, True)]


def commands(model, csv, iec, dir_):
    m = "'%s'" % model
    result = write(dir_, os.path.basename(model) + ".result.json",
                   '{"schema_version": "1.0", "model": "%s", "semantics": "%s", "properties": []}'
                   % (model, "iec61131" if iec else "grafcet"))
    html = os.path.join(dir_, "r.html")
    rows = []
    for e in ["explicit", "bdd", "bmc", "kind", "ic3", "auto"]:
        rows.append(("check", e, "check %s --engine %s" % (m, e)))
    for e in ["explicit", "bdd", "auto"]:
        rows.append(("query", e, "query %s '#Y' --engine %s" % (m, e)))
    rows += [("rsg", "explicit", "rsg " + m),
             ("simulate", "-", "simulate %s --inputs '%s'" % (m, csv)),
             ("export", "-", "export %s --to %s" % (m, "nusmv" if iec else "dot")),
             ("report", "-", "report '%s' --html '%s'" % (result, html)),
             ("info", "-", "info " + m),
             ("lint", "-", "lint " + m)]
    for e in ["explicit", "bdd", "ic3"]:
        rows.append(("equiv", e, "equiv %s %s --engine %s" % (m, m, e)))
    return rows


LIMITS = [("time", "--timeout " + TIMEOUT),
          ("memory", "--memory %s --timeout %s" % (MEMORY, SAFETY)),
          ("states", "--max-states %s --timeout %s" % (STATES, SAFETY))]


def run(sfcv, args):
    start = time.monotonic()
    p = subprocess.Popen("exec '%s' %s --quiet >/dev/null 2>/dev/null </dev/null" % (sfcv, args),
                         shell=True)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    return code, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


def cell(code, wall, cpu, mib):
    word = {0: "held", 1: "held", 2: "exit 2", 3: "exit 3"}.get(code, "exit %d" % code)
    return "%s %.1f/%.1f s %d MB" % (word, wall, cpu, mib)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sfcv")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    sfcv = os.path.abspath(a.sfcv)
    with tempfile.TemporaryDirectory(prefix="sfcv-limits-") as dir_:
        kinds = inputs(dir_)
        jobs = []
        for k, (name, model, csv, iec) in enumerate(kinds):
            for r, (sub, engine, args) in enumerate(commands(model, csv, iec, dir_)):
                for l, (limit, flags) in enumerate(LIMITS):
                    jobs.append(((r, sub, engine), (k, l), args + " " + flags))
        results = {}
        with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
            futures = {pool.submit(run, sfcv, args): (row, col) for row, col, args in jobs}
            for f in concurrent.futures.as_completed(futures):
                results[futures[f]] = f.result()
        header = "| subcommand | engine |"
        rule = "|---|---|"
        for name, _, _, _ in kinds:
            for limit, _ in LIMITS:
                header += " %s, %s |" % (name, limit)
                rule += "---|"
        print(header)
        print(rule)
        for row in sorted({row for row, _, _ in jobs}):
            line = "| %s | %s |" % (row[1], row[2])
            for k in range(len(kinds)):
                for l in range(len(LIMITS)):
                    line += " %s |" % cell(*results[(row, (k, l))])
            print(line)
            sys.stdout.flush()


if __name__ == "__main__":
    main()
