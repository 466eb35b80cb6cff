#!/bin/sh
# SARIF logs of sfcv check validate against the SARIF 2.1.0 schema (the subset in tests/data/sarif)
# and meet GitHub code scanning's requirements (validate_sarif.py --github, explicit assertions):
# the chemical plant (an IEC text chart: a violated property, violated standard checks, every
# check), a Grafcet chart, a spec file, and an unknown verdict (a state limit). URIs are relative
# to --sarif-root (the source tree, as a repository root would be). Then: the default root is
# the git work tree or the working directory, and a rule id does not change between runs.
# The tool's informationUri is the build's SFCV_INFORMATION_URI, absent when that is empty.
# Usage: sarif_schema_test.sh SFCV SOURCE_DIR INFORMATION_URI
set -eu
sfcv=$1
src=$2
information_uri=${3-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
plant="$src/examples/chemical_plant/chemical_plant.st"
root="--sarif-root $src"
"$sfcv" check "$plant" --quiet --checks all --ctl 'AG !(V2 & V4)' --trace none $root --sarif "$dir/plant.sarif" >/dev/null || [ $? -eq 1 ]
"$sfcv" check "$src/examples/pallet_transfer/pallet_transfer.g7" --quiet --ctl 'AG !(X10 & X25)' --checks reachable --trace none \
  $root --sarif "$dir/pallet.sarif" >/dev/null 2>&1 || [ $? -le 1 ]
"$sfcv" check "$plant" --quiet --spec "$src/examples/chemical_plant/requirements.spec" $root --sarif "$dir/spec.sarif" >/dev/null || [ $? -eq 1 ]
"$sfcv" check "$plant" --quiet --max-states 3 --ctl 'AG !(V1 & V3)' --trace none $root --sarif "$dir/unknown.sarif" >/dev/null || [ $? -eq 3 ]
grep -q '"level": "warning"' "$dir/unknown.sarif"
# The same question twice: the same rule id and fingerprints (code scanning tracks alerts by them).
"$sfcv" check "$plant" --quiet --checks all --ctl 'AG  !(V2&V4)' --trace none $root --sarif "$dir/again.sarif" >/dev/null || [ $? -eq 1 ]
/usr/bin/python3 - "$dir/plant.sarif" "$dir/again.sarif" <<'PY'
import json, sys
a, b = (json.load(open(p))["runs"][0] for p in sys.argv[1:])
assert [r["id"] for r in a["tool"]["driver"]["rules"]] == [r["id"] for r in b["tool"]["driver"]["rules"]], "rule ids differ"
assert [r["partialFingerprints"] for r in a["results"]] == [r["partialFingerprints"] for r in b["results"]], "fingerprints differ"
assert a["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"] == \
    {"uri": "examples/chemical_plant/chemical_plant.st", "uriBaseId": "SRCROOT"}, a["results"][0]["locations"]
PY
# Without --sarif-root, from a directory that is no git work tree: relative to it.
mkdir "$dir/work" && cp "$plant" "$dir/work/plant.st"
(cd "$dir/work" && "$sfcv" check plant.st --quiet --ctl 'AG !(V2 & V4)' --trace none --sarif out.sarif >/dev/null || [ $? -eq 1 ])
grep -q '"uri": "plant.st"' "$dir/work/out.sarif"
exec /usr/bin/python3 "$src/tests/report/validate_sarif.py" --github "--information-uri=$information_uri" "$src/tests/data/sarif/sarif-2.1.0-subset.schema.json" \
  "$dir/plant.sarif" "$dir/pallet.sarif" "$dir/spec.sarif" "$dir/unknown.sarif" "$dir/work/out.sarif"
