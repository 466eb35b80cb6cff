#!/bin/sh
# SARIF logs of sfcv check validate against the SARIF 2.1.0 schema (the subset in tests/data/sarif):
# the chemical plant (an IEC text chart: a violated property, violated standard checks), a
# Grafcet chart, and an unknown verdict (a state limit). Usage: sarif_schema_test.sh SFCV SOURCE_DIR
set -eu
sfcv=$1
src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
plant="$src/examples/chemical_plant/chemical_plant.st"
"$sfcv" check "$plant" --quiet --checks all --ctl 'AG !(V2 & V4)' --trace none --sarif "$dir/plant.sarif" >/dev/null || [ $? -eq 1 ]
"$sfcv" check "$src/examples/pallet_transfer/pallet_transfer.g7" --quiet --ctl 'AG !(X10 & X25)' --checks reachable --trace none \
  --sarif "$dir/pallet.sarif" >/dev/null 2>&1 || [ $? -le 1 ]
"$sfcv" check "$plant" --quiet --max-states 3 --ctl 'AG !(V1 & V3)' --trace none --sarif "$dir/unknown.sarif" >/dev/null || [ $? -eq 3 ]
grep -q '"level": "warning"' "$dir/unknown.sarif"
exec /usr/bin/python3 "$src/tests/report/validate_sarif.py" "$src/tests/data/sarif/sarif-2.1.0-subset.schema.json" \
  "$dir/plant.sarif" "$dir/pallet.sarif" "$dir/unknown.sarif"
