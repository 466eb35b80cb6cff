#!/bin/sh
# Every kind of `sfcv check --json` output validates against the shipped schema
# (share/sfcv/check-result.schema.json): violated properties with traces, every standard check,
# coverage, patterns (description, vacuity), a spec file (where), an LTL lasso (loop_start), a
# Grafcet, an unknown verdict (a state limit), the BDD and IC3 engines (counts null or exact);
# and the JSON error object of a bad model, a bad formula, a bad option and a bad limit, with the
# exit code unchanged. Then `sfcv info`, `lint`, `query` and `rsg --json` against their schemas
# (a Grafcet, a model with lint warnings, every sort of query answer, an incomplete graph).
# Usage: json_schema_test.sh SFCV SOURCE_DIR
set -eu
sfcv=$1
src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
plant="$src/examples/chemical_plant/chemical_plant.st"
pallet="$src/examples/pallet_transfer/pallet_transfer.g7"
n=0
# run EXPECTED_EXIT ARGS...: sfcv ARGS --json > next file; the exit code must be EXPECTED_EXIT.
run() {
  expected=$1
  shift
  n=$((n + 1))
  set +e
  "$sfcv" "$@" --json --quiet >"$dir/out$n.json" 2>"$dir/err$n.txt"
  code=$?
  set -e
  if [ "$code" -ne "$expected" ]; then
    echo "exit $code, expected $expected: sfcv $*"
    cat "$dir/err$n.txt"
    exit 1
  fi
}
# A shard's result (sfcv check --shard I/N): the "shard" key (docs/distributed.md).
run 1 check "$plant" --ctl 'AG !(V2 & V4)' --checks reachable --shard 1/2
run 1 check "$plant" --checks all --ctl 'AG !(V2 & V4)' --ctl 'EF s13'
run 1 check "$plant" --checks all --coverage --engine explicit
run 1 check "$plant" --spec "$src/examples/chemical_plant/requirements.spec"
run 0 check "$plant" --pattern 'absence(V1 & V3)' --ctl 'AG (s2 -> V1)' --all
run 1 check "$plant" --ltl 'G F s9'
run 1 check "$plant" --ctl 'AG !(V2 & V4)' --engine bdd --fair start --assume '!(LIS1plus & LIS1minus)'
run 1 check "$plant" --ctl 'AG !(V2 & V4)' --engine ic3
run 3 check "$plant" --ctl 'AG !(V1 & V3)' --max-states 3
run 1 check "$pallet" --ctl 'AG !(X10 & X25)' --checks reachable,dead-transitions
run 1 check "$plant" --ctl 'AG !(V2 & V4)' --trace vcd --trace-dir "$dir/traces"
errors_from=$((n + 1))
run 2 check "$dir/missing.st"
run 2 check "$plant" --ctl 'AG !(V2 &'
run 2 check "$plant" --no-such-option
run 2 check "$plant" --timeout -1
run 2 check "$plant" --trace vcd
run 2 info "$dir/missing.st"
# The error documents name their kind and keep the exit code.
i=$errors_from
while [ "$i" -le "$n" ]; do
  grep -q '"error"' "$dir/out$i.json" || { echo "out$i.json: no error object"; cat "$dir/out$i.json"; exit 1; }
  grep -q '"exit_code": 2' "$dir/out$i.json" || { echo "out$i.json: exit_code is not 2"; exit 1; }
  i=$((i + 1))
done
/usr/bin/python3 "$src/tests/report/validate_json.py" "$src/share/sfcv/check-result.schema.json" "$dir"/out*.json
# The other commands' JSON against their schemas (share/sfcv/{info,lint,query,rsg}.schema.json):
# doc SCHEMA EXPECTED_EXIT ARGS...: sfcv ARGS --json > a file checked against SCHEMA.
doc() {
  schema=$1
  shift
  mkdir -p "$dir/$schema"
  run "$@"
  mv "$dir/out$n.json" "$dir/$schema/$n.json"
}
cat >"$dir/lint_me.st" <<'ST'
PROGRAM P
  VAR_INPUT a : BOOL; END_VAR
  VAR_OUTPUT q : BOOL; END_VAR
  VAR x : BOOL; END_VAR
  INITIAL_STEP S0: END_STEP
  STEP S1: q(N); END_STEP
  STEP S2: END_STEP
  TRANSITION FROM S0 TO S1 := a AND x; END_TRANSITION
  TRANSITION FROM S1 TO S0 := NOT a; END_TRANSITION
END_PROGRAM
ST
pistons="$src/examples/pistons/pistons.g7"
doc info 0 info "$plant"
doc info 0 info "$pallet"
doc info 0 info "$dir/lint_me.st"
doc lint 0 lint "$plant"
doc lint 0 lint "$dir/lint_me.st"
grep -q '"severity": "warning"' "$dir/lint/$n.json" || { echo "lint_me.st: no warning in the JSON"; exit 1; }
doc query 0 query "$pallet" 'Act({10, 25})' 'Y - Pred(Y0, T)' 'Steps - {1}' 'T' '#Y' 'Y0 != {}'
doc query 1 query "$pallet" 'Act({10, 25}) = {}' --assert
doc query 0 query "$pistons" --use global_deadlock --assert
doc rsg 0 rsg "$pistons"
doc rsg 3 rsg "$pallet" --max-states 50
grep -q '"complete": false' "$dir/rsg/$n.json" || { echo "rsg --max-states: not incomplete"; exit 1; }
for schema in info lint query rsg; do
  /usr/bin/python3 "$src/tests/report/validate_json.py" "$src/share/sfcv/$schema.schema.json" "$dir/$schema"/*.json
done
