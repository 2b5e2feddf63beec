#!/bin/bash
# The test parameter_reference: doc/parameters.md must be the output of
# `qsmpm --print-parameters-markdown`.
#
#   parameter_reference.sh <driver> <doc/parameters.md> <generated copy>
set -euo pipefail
driver=$1
committed=$2
generated=$3
"$driver" --print-parameters-markdown >"$generated"
if diff -u "$committed" "$generated"; then
  echo "PASS: doc/parameters.md is up to date"
else
  echo "FAIL: doc/parameters.md is out of date: run make parameter_reference"
  exit 1
fi
