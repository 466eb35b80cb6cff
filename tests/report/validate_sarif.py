#!/usr/bin/python3
"""Validates SARIF logs against a JSON schema with Debian's python3-jsonschema, then (with
--github) against what GitHub code scanning requires of an upload, written out as explicit
assertions: the fields its SARIF documentation lists as required or used, and the rules the
SARIF Multitool's GitHub validation (GH1001-GH1007) enforces.

usage: validate_sarif.py [--github] SCHEMA LOG... ; exit 0 when every log is valid, 1 otherwise,
77 (skipped) when jsonschema is not installed.
"""
import json
import re
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(77)

args = sys.argv[1:]
github = "--github" in args
args = [a for a in args if a != "--github"]
# --information-uri=URI: the tool's informationUri must be exactly the one the build was given
# (CMake's SFCV_INFORMATION_URI), and absent when that is empty: never an invented address.
information_uri = None
for a in list(args):
    if a.startswith("--information-uri="):
        information_uri = a.split("=", 1)[1]
        args.remove(a)


def github_problems(log):
    """Each string names one way the log would fail or degrade a GitHub code-scanning upload."""
    out = []
    if log.get("version") != "2.1.0" or "$schema" not in log:
        out.append("version 2.1.0 and $schema are required")
    for run in log["runs"]:
        driver = run["tool"]["driver"]
        for key in ("name", "version"):
            if not driver.get(key):
                out.append(f"tool.driver.{key} is missing")
        if "informationUri" in driver and not re.match(r"^https?://", driver["informationUri"]):
            out.append("tool.driver.informationUri is not an absolute http(s) URI")
        if information_uri is not None and driver.get("informationUri", "") != information_uri:
            out.append(f"tool.driver.informationUri is {driver.get('informationUri')!r}, "
                       f"the build's SFCV_INFORMATION_URI {information_uri!r}")
        bases = run.get("originalUriBaseIds", {})
        for name, base in bases.items():
            if not re.match(r"^file:///.*/$", base.get("uri", "")):
                out.append(f"originalUriBaseIds.{name} is not an absolute file:// directory URI")
        rules = driver.get("rules", [])
        ids = [r["id"] for r in rules]
        if len(set(ids)) != len(ids):
            out.append("rule ids are not unique")
        for r in rules:
            rid = r["id"]
            # Stable: made of the check's name or a digest, never the raw formula text.
            if not re.match(r"^(check|property)/[A-Za-z0-9_.-]+$", rid):
                out.append(f"rule id {rid!r} is not a stable identifier")
            for key in ("shortDescription", "fullDescription", "help"):
                if not r.get(key, {}).get("text"):
                    out.append(f"rule {rid}: {key}.text is missing")
            if r.get("defaultConfiguration", {}).get("level") not in ("error", "warning", "note", "none"):
                out.append(f"rule {rid}: defaultConfiguration.level is missing")

        def check_location(where, loc):
            phys = loc.get("physicalLocation")
            if not phys:
                out.append(f"{where}: no physicalLocation (GH1001)")
                return
            art = phys.get("artifactLocation", {})
            uri = art.get("uri", "")
            if not uri or re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", uri) or uri.startswith("/"):
                out.append(f"{where}: uri {uri!r} is not relative to the repository (GH1005)")
            if art.get("uriBaseId") and art["uriBaseId"] not in bases:
                out.append(f"{where}: uriBaseId {art['uriBaseId']} is not in originalUriBaseIds")
            if phys.get("region", {}).get("startLine", 0) < 1:
                out.append(f"{where}: region.startLine is missing (GH1003)")

        results = run.get("results", [])
        if len(results) > 25000:
            out.append("more than 25,000 results (GH1004)")
        for k, res in enumerate(results):
            where = f"result {k}"
            rid = res.get("ruleId")
            if rid not in ids:
                out.append(f"{where}: ruleId {rid!r} names no rule")
            elif "ruleIndex" in res and ids[res["ruleIndex"]] != rid:
                out.append(f"{where}: ruleIndex does not point to ruleId")
            text = res.get("message", {}).get("text", "")
            if not text or re.search(r"\{[0-9]+\}", text) or "id" in res.get("message", {}):
                out.append(f"{where}: message.text is not a fully formatted string (GH1007)")
            if res.get("level") not in ("error", "warning", "note", "none"):
                out.append(f"{where}: level is missing")
            locs = res.get("locations", [])
            if not 1 <= len(locs) <= 10:
                out.append(f"{where}: {len(locs)} locations (code scanning shows 1 to 10)")
            for loc in locs:
                check_location(where, loc)
            if len(res.get("relatedLocations", [])) > 1000:
                out.append(f"{where}: more than 1,000 related locations (GH1004)")
            for loc in res.get("relatedLocations", []):
                check_location(where + " related location", loc)
            fp = res.get("partialFingerprints")
            if not fp or not all(isinstance(v, str) and v for v in fp.values()):
                out.append(f"{where}: partialFingerprints are missing")
            for flow in res.get("codeFlows", []):
                for thread in flow["threadFlows"]:
                    if len(thread["locations"]) > 10000:
                        out.append(f"{where}: a thread flow of more than 10,000 locations (GH1004)")
                    for tfl in thread["locations"]:
                        if "location" not in tfl:
                            out.append(f"{where}: a thread flow location is not inline (GH1002)")
                        else:
                            check_location(where + " code flow", tfl["location"])
        # Provenance: who ran what, when, on which files.
        inv = run.get("invocations", [])
        if not inv or "commandLine" not in inv[0] or "startTimeUtc" not in inv[0]:
            out.append("invocations[0] with commandLine and startTimeUtc is missing")
        for a in run.get("artifacts", []):
            if not re.match(r"^[0-9a-f]{64}$", a.get("hashes", {}).get("sha-256", "")):
                out.append("an artifact has no sha-256 hash")
        if not run.get("artifacts"):
            out.append("artifacts (the inputs with their hashes) are missing")
    return out


schema = json.load(open(args[0]))
validator = jsonschema.Draft7Validator(schema, format_checker=jsonschema.FormatChecker())
bad = 0
for path in args[1:]:
    log = json.load(open(path))
    errors = sorted(validator.iter_errors(log), key=lambda e: list(e.path))
    for e in errors:
        print(f"{path}: {'/'.join(map(str, e.path))}: {e.message}")
    bad += bool(errors)
    if not log["runs"][0].get("results"):
        print(f"{path}: no results: nothing was validated")
        bad += 1
    if github:
        problems = github_problems(log)
        for p in problems:
            print(f"{path}: GitHub: {p}")
        bad += bool(problems)
sys.exit(1 if bad else 0)
