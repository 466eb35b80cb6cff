#!/usr/bin/env python3
"""The examples of docs/distributed.md, run locally: the shard command lines of the GitHub
Actions matrix and the GitLab CI job (taken from examples/distributed/*.yml, with the matrix
value or CI_NODE_INDEX each copy would get), the Slurm array script (run with
SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT set, as Slurm would; the command line it runs is
the one the doc names) and GNU parallel on one machine. Each merged report must equal the
single run's JSON once timings and dates are left out, and exit as it did.
Usage: distributed_examples_test.py SFCV SOURCE_DIR"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import yaml

sfcv, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
examples = os.path.join(src, "examples", "distributed")
work = tempfile.mkdtemp(prefix="sfcv-distributed-")
failures = []


def without_timings(j):
    if isinstance(j, dict):
        return {k: without_timings(v) for k, v in j.items() if k not in ("seconds", "date")}
    if isinstance(j, list):
        return [without_timings(v) for v in j]
    return j


def check(what, ok, detail=""):
    if not ok:
        failures.append(what + (": " + detail if detail else ""))


# The project of the CI examples: plant.st and plant.spec in the working directory, `sfcv` on
# PATH (a wrapper that logs each command line, then runs this build's sfcv).
shutil.copy(os.path.join(src, "examples/chemical_plant/chemical_plant.st"), work + "/plant.st")
shutil.copy(os.path.join(src, "examples/chemical_plant/requirements.spec"), work + "/plant.spec")
os.makedirs(work + "/bin")
log = work + "/commands.log"
with open(work + "/bin/sfcv", "w") as f:
    f.write('#!/bin/sh\nprintf "%s\\n" "sfcv $*" >> "' + log + '"\nexec "' + sfcv + '" "$@"\n')
os.chmod(work + "/bin/sfcv", 0o755)
env = dict(os.environ, PATH=work + "/bin:" + os.environ["PATH"])
args = "plant.st --checks all --spec plant.spec"


def run(cmd, cwd, extra_env=None, shell=True):
    e = dict(env, **(extra_env or {}))
    return subprocess.run(cmd, cwd=cwd, env=e, shell=shell, capture_output=True, text=True)


single = run("sfcv check " + args + " --json --quiet", work)
expected = json.dumps(without_timings(json.loads(single.stdout)), sort_keys=True)


def expect_merge(where, label):
    shards = sorted(f for f in os.listdir(where) if f.startswith("shard-") and f.endswith(".json"))
    merged = run("sfcv merge " + " ".join(shards) + " --json --quiet", where)
    check(label + ": merge exit code", merged.returncode == single.returncode, merged.stderr)
    if merged.stdout:
        got = json.dumps(without_timings(json.loads(merged.stdout)), sort_keys=True)
        check(label + ": merged JSON equals the single run's", got == expected)


def fresh(name):
    d = os.path.join(work, name)
    os.makedirs(d)
    for f in ("plant.st", "plant.spec"):
        shutil.copy(os.path.join(work, f), d)
    return d


# GitHub Actions: each matrix value's `run:` of the shard job, then the merge job's.
gha = yaml.safe_load(open(os.path.join(examples, "github-actions.yml")))
d = fresh("github")
shard_job = gha["jobs"]["shard"]
for value in shard_job["strategy"]["matrix"]["shard"]:
    for step in shard_job["steps"]:
        if "run" in step:
            cmd = step["run"].replace("${{ matrix.shard }}", str(value))
            r = run(cmd, d, {k: str(v) for k, v in gha["env"].items()})
            check("github shard %d" % value, r.returncode == 0, r.stderr)
expect_merge(d, "github")
merge_run = [s["run"] for s in gha["jobs"]["merge"]["steps"] if "run" in s][0]
r = run(merge_run, d)
check("github merge job", r.returncode == single.returncode and os.path.exists(d + "/sfcv.xml")
      and os.path.exists(d + "/sfcv.sarif"), r.stderr)

# GitLab CI: `parallel: N` copies with CI_NODE_INDEX 1..N.
gl = yaml.safe_load(open(os.path.join(examples, "gitlab-ci.yml")))
d = fresh("gitlab")
job = gl["sfcv-shard"]
for index in range(1, job["parallel"] + 1):
    for cmd in job["script"]:
        r = run(cmd, d, dict(gl["variables"], CI_NODE_INDEX=str(index),
                             CI_NODE_TOTAL=str(job["parallel"])))
        check("gitlab shard %d" % index, r.returncode == 0, r.stderr)
expect_merge(d, "gitlab")
for cmd in gl["sfcv-merge"]["script"]:
    r = run(cmd, d)
    check("gitlab merge job", r.returncode == single.returncode and os.path.exists(d + "/sfcv.xml"),
          r.stderr)

# Slurm: the array script per task; its command line is the doc's.
d = fresh("slurm")
open(log, "w").close()
for task in range(1, 5):
    r = run(["sh", os.path.join(examples, "slurm-array.sh"), "plant.st", "--checks", "all",
             "--spec", "plant.spec"], d,
            {"SLURM_ARRAY_TASK_ID": str(task), "SLURM_ARRAY_TASK_COUNT": "4"}, shell=False)
    check("slurm task %d" % task, r.returncode == 0, r.stderr)
lines = open(log).read().splitlines()
check("slurm command lines", lines == ["sfcv check " + args + " --json --quiet --shard %d/4" % t
                                       for t in range(1, 5)], "\n".join(lines))
expect_merge(d, "slurm")

# GNU parallel on one machine (Debian's parallel, scripts/install-deps.sh).
if shutil.which("parallel"):
    d = fresh("parallel")
    r = run(["sh", os.path.join(examples, "parallel.sh"), "4", "plant.st", "--checks", "all",
             "--spec", "plant.spec"], d, {"OUT": d}, shell=False)
    check("parallel.sh exit code", r.returncode == single.returncode, r.stderr)
    check("parallel.sh prints the merged report", "violated" in r.stdout, r.stdout)
    expect_merge(d, "parallel")
else:
    failures.append("GNU parallel is not installed (scripts/install-deps.sh installs it)")

shutil.rmtree(work)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
