#!/bin/sh
# The Grafcet BDD engine under valgrind's memcheck (issue 53 item 10): `sfcv check --engine bdd`
# on examples/pistons/pistons.g7, where BuDDy's not_rec used to leave apply-cache memory unwritten
# that apply_rec then read (in GrafcetClosure::forward; docs/engines.md), with a counterexample
# and a witness to build; then the BDD facade's truth-table test and the quick GrafcetBdd tests.
# Any memcheck error fails. Skipped, visibly, without valgrind (scripts/install-deps.sh installs
# it). Usage: valgrind_grafcet_bdd_test.sh SFCV TEST_ENGINE SOURCE_DIR
set -u
sfcv=$1
tests=$2
src=$3
if ! command -v valgrind >/dev/null 2>&1; then
  echo "valgrind_grafcet_bdd: skipped, valgrind is not installed"
  exit 77
fi
memcheck="valgrind --quiet --error-exitcode=99 --leak-check=no"

# AG !X12 is violated (exit 1) and EF X22 holds: both traces are built.
$memcheck "$sfcv" check "$src/examples/pistons/pistons.g7" --quiet --engine bdd --checks all \
  --ctl 'AG !((O1 | I1) & (O2 | I2))' --ctl 'EF X22' --ctl 'AG !X12' >/dev/null
status=$?
if [ "$status" -ne 1 ]; then
  echo "valgrind_grafcet_bdd: sfcv check on pistons.g7 exited $status (99: memcheck errors above)"
  exit 1
fi

$memcheck "$tests" --gtest_brief=1 --gtest_filter='BddManager.*:GrafcetBdd.InstabilityIsDetectedSymbolically:GrafcetBdd.IntegerInputsComputedWithKeepTheirExactValues:GrafcetBdd.StepsCrossedAtTheStartAreReachedApart:GrafcetBdd.VariableWrittenByContinuousAndStoredActionsIsReadAsEither:GrafcetBdd.StoredValueOutOfRangeIsARangeError'
status=$?
if [ "$status" -ne 0 ]; then
  echo "valgrind_grafcet_bdd: the BDD unit tests exited $status under valgrind (99: memcheck errors above)"
  exit 1
fi
echo "valgrind_grafcet_bdd: no memcheck error"
