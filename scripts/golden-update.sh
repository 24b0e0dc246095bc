#!/usr/bin/env bash
# Regenerates the golden cases' expected.json (tests/golden/<case>/) from the
# current build, after a deliberate change of output. Review the diff
# (git diff tests/golden) and say in the commit why the values moved.
#   scripts/golden-update.sh [build-dir] [case-filter]
# case-filter: a gtest pattern over the case names, '-' written as '_'
# (e.g. 'sar_*'); default: every case.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
filter=${2:-*}
cmake --build "$build" --target ris ris_tests
RIS_GOLDEN_UPDATE=1 "$build/ris_tests" --gtest_filter="Cases/Golden.ProductsMatchExpected/$filter" >/dev/null
"$build/ris_tests" --gtest_filter="Cases/Golden.ProductsMatchExpected/$filter"
git status --short tests/golden
