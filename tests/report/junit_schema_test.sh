#!/bin/sh
# JUnit reports of sfcv check validate against Jenkins' junit-10.xsd structure
# (tests/data/junit/junit-10.xsd) with xmllint (Debian's libxml2-utils): failures, errors
# (unknown), skipped (n/a), a spec file's properties, a Grafcet; two runs on one model have
# distinct suite names; the old report (file/line on a test case, 6 decimals) is rejected.
# Usage: junit_schema_test.sh SFCV SOURCE_DIR
set -eu
sfcv=$1
src=$2
command -v xmllint >/dev/null || { echo "xmllint (libxml2-utils) is not installed: skipped"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
xsd="$src/tests/data/junit/junit-10.xsd"
plant="$src/examples/chemical_plant/chemical_plant.st"
"$sfcv" check "$plant" -q --checks all --ctl 'AG !(V2 & V4)' --junit "$dir/all.xml" >/dev/null || [ $? -eq 1 ]
"$sfcv" check "$plant" -q --ctl 'AG !(V1 & V3)' --max-states 3 --junit "$dir/unknown.xml" >/dev/null || [ $? -eq 3 ]
"$sfcv" check "$plant" -q --spec "$src/examples/chemical_plant/requirements.spec" --junit "$dir/spec.xml" >/dev/null || [ $? -eq 1 ]
"$sfcv" check "$src/examples/pallet_transfer/pallet_transfer.g7" -q --checks reachable --ctl 'AG !(X10 & X25)' \
  --junit "$dir/pallet.xml" >/dev/null 2>&1 || [ $? -le 1 ]
grep -q '<failure' "$dir/all.xml"
grep -q '<skipped' "$dir/all.xml"   # conflicts: n/a under the standard priority
grep -q '<error' "$dir/unknown.xml"
xmllint --noout --schema "$xsd" "$dir/all.xml" "$dir/unknown.xml" "$dir/spec.xml" "$dir/pallet.xml"
# Two runs on one model: two suite names (CI servers merge test cases by suite and name).
s1=$(sed -n 's/.*<testsuite name="\([^"]*\)".*/\1/p' "$dir/all.xml")
s2=$(sed -n 's/.*<testsuite name="\([^"]*\)".*/\1/p' "$dir/unknown.xml")
[ -n "$s1" ] && [ "$s1" != "$s2" ] || { echo "suite names not distinct: '$s1' '$s2'"; exit 1; }
# The schema is not vacuous: what Jenkins rejected in the old reports fails here too.
sed 's/<testcase /<testcase file="m.st" line="3" /' "$dir/all.xml" >"$dir/file_line.xml"
sed 's/time="\([0-9]*\)\.\([0-9]*\)"/time="\1.\2000"/' "$dir/all.xml" >"$dir/six_decimals.xml"
sed 's/<testsuites /<testsuites skipped="1" /' "$dir/all.xml" >"$dir/skipped_root.xml"
for bad in file_line six_decimals skipped_root; do
  if xmllint --noout --schema "$xsd" "$dir/$bad.xml" 2>/dev/null; then
    echo "$bad.xml was accepted"
    exit 1
  fi
done
echo "JUnit reports valid against junit-10.xsd; suites '$s1' and '$s2'"
