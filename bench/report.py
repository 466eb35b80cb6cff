#!/usr/bin/env python3
"""Turns bench/run's results.csv into a Markdown table (one row per model) with ratios.

sfcv's time for the ratios is its faster engine that finished (explicit or BDD); a tool that did
not finish is shown with its status and gets no ratio.
"""
import csv
import sys
from collections import OrderedDict


def cell(r):
    if r is None:
        return "-"
    if r["status"] != "ok" or not r["seconds"]:
        return r["status"] if r["status"] != "ok" else "?"
    mb = f", {int(r['peak_kb']) / 1024:.0f} MB" if r["peak_kb"] else ""
    return f"{float(r['cpu_seconds']):.2f} s ({float(r['seconds']):.2f} s wall{mb})"


def secs(r):
    """CPU seconds (user + system) of a finished run."""
    return float(r["cpu_seconds"]) if r and r["status"] == "ok" and r["cpu_seconds"] else None


def rates(r):
    """States and edges the explicit engine explored per CPU second (what it explored: a search
    that stops at a violation explores less than the whole space)."""
    s = secs(r)
    if s is None or not r["states"] or not r["edges"]:
        return "-"
    s = max(s, 0.01)
    return f"{float(r['states']) / s / 1e6:.2f} M, {float(r['edges']) / s / 1e6:.2f} M"


def main(path):
    cases = OrderedDict()
    with open(path) as f:
        for r in csv.DictReader(f):
            cases.setdefault((r["family"], r["size"], r["variant"]), {})[r["tool"]] = r
    cols = ["family", "N", "variant", "states", "edges", "sfcv explicit", "explicit states/s, edges/s",
            "sfcv BDD", "sfcv IC3", "sfcv RSG",
            "Spin (pan)", "Spin states", "ABC pdr", "NuSMV -dynamic", "verdicts", "Spin / sfcv",
            "ABC / sfcv", "IC3 / ABC", "NuSMV / sfcv BDD"]
    print("| " + " | ".join(cols) + " |")
    print("|" + "---|" * len(cols))
    for (fam, size, variant), t in cases.items():
        ex, bdd, rsg = t.get("sfcv-explicit"), t.get("sfcv-bdd"), t.get("sfcv-rsg")
        ic3 = t.get("sfcv-ic3")
        spin, abc, nusmv = t.get("spin"), t.get("abc-pdr"), t.get("nusmv")
        states = edges = ""
        for r in (ex, rsg, bdd):
            if r and r["status"] == "ok" and r["states"]:
                states, edges = r["states"], r["edges"]
                break
        # Definitive verdicts must agree; an "unknown" (e.g. Spin's depth bound) is listed apart.
        definite = {r["verdict"] for r in t.values() if r["verdict"] in ("holds", "violated")}
        unsure = [k for k, r in t.items() if r["verdict"] == "unknown"]
        if len(definite) > 1:
            verdict = "DISAGREE: " + ", ".join(f"{k}={r['verdict']}" for k, r in t.items())
        else:
            verdict = definite.pop() if definite else ""
            if unsure:
                verdict += " (unknown: " + ", ".join(unsure) + ")"
        sfcv_times = [s for s in (secs(ex), secs(bdd), secs(ic3), secs(rsg)) if s is not None]
        best = min(sfcv_times) if sfcv_times else None

        def ratio(r, base=best):
            s = secs(r)
            if s is None or base is None:
                return "-"
            return f"{s / max(base, 0.01):.1f}"

        spin_cell = cell(spin)
        if spin and spin["prep_seconds"]:
            spin_cell += f" (+{float(spin['prep_seconds']):.1f} s build)"
        # The IC3 target: IC3 / ABC <= 2 wherever ABC needs >= 0.1 s.
        ic3_vs_abc = "-"
        if secs(ic3) is not None and secs(abc) is not None:
            ic3_vs_abc = f"{max(secs(ic3), 0.01) / max(secs(abc), 0.01):.2f}"
        row = [fam, size, variant, states, edges, cell(ex), rates(ex), cell(bdd), cell(ic3), cell(rsg), spin_cell,
               spin["states"] if spin and spin["states"] else "-", cell(abc), cell(nusmv), verdict,
               ratio(spin), ratio(abc), ic3_vs_abc, ratio(nusmv, secs(bdd))]
        print("| " + " | ".join(row) + " |")
    print()
    print("Cells: CPU seconds (user + system) (wall-clock seconds, peak resident memory), from "
          "GNU time. IC3 / ABC is IC3's CPU time over ABC pdr's. Other ratios divide the other tool's CPU time by sfcv's faster engine's (times "
          "under 0.01 s count as 0.01 s). Spin's time is pan's search; its build (spin -a and "
          "the C compiler, wall time) is shown apart. NuSMV runs `-dcx -dynamic` on `sfcv export "
          "--to nusmv`; its ratio is against sfcv's BDD engine. States/s and edges/s: what the explicit "
          "engine explored (up to the first violation for a violated invariant) per CPU second.")

    bounded(cases)


def bounded(cases):
    """BMC against ABC bmc3 on the violated invariants, k-induction against ABC ind (the
    inductive step with simple-path constraints on demand) on those that hold."""
    pairs = [("sfcv-bmc", "abc-bmc3"), ("sfcv-kind", "abc-ind")]
    rows = []
    for (fam, size, variant), t in cases.items():
        for ours, theirs in pairs:
            a, b = t.get(ours), t.get(theirs)
            if a is None and b is None:
                continue
            r = "-"
            if secs(a) is not None and secs(b) is not None:
                r = f"{max(secs(a), 0.01) / max(secs(b), 0.01):.2f}"
            verdicts = "/".join((x["verdict"] or x["status"]) if x else "-" for x in (a, b))
            rows.append([fam, size, variant, ours, cell(a), theirs, cell(b), verdicts, r])
    if not rows:
        return
    print()
    cols = ["family", "N", "variant", "sfcv", "time", "ABC", "time", "verdicts", "sfcv / ABC"]
    print("| " + " | ".join(cols) + " |")
    print("|" + "---|" * len(cols))
    for row in rows:
        print("| " + " | ".join(row) + " |")
    print()
    print("sfcv / ABC: CPU time of sfcv bmc over ABC bmc3, of sfcv kind over ABC ind -u "
          "(times under 0.01 s count as 0.01 s); both read the same `sfcv export --to aiger`.")


if __name__ == "__main__":
    main(sys.argv[1])
