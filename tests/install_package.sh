#!/bin/bash
# The test install_package: qsmpm as a library users build on.
#
#   install_package.sh <qsmpm build directory> <work directory>
#
#  1. cmake --install <build> --prefix <work>/prefix (any writable prefix);
#  2. configure the user project tests/install_package (app.cc, the user
#     model usermodel.cc) with -DCMAKE_PREFIX_PATH=<work>/prefix, build it;
#  3. run the app on 2 ranks: the user model "K-G elastic" against the
#     built-in linear elastic (1e-10) and the analytical plate force (1e-6);
#  4. <prefix>/bin/qsmpm --version;
#  5. the installed driver with --plugin libusermodel.so on kg.prm (user
#     model selected in the .prm file) on 2 ranks: its reactions.csv against
#     the analytical plate force (1e-6);
#  6. --plugin with a missing library must fail and name it.
# Every check prints a PASS or FAIL line; any failure exits non-zero.
set -euo pipefail

build=$(cd "$1" && pwd)
work=$2
source_dir=$(cd "$(dirname "$0")/install_package" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  OMPI_MCA_rmaps_base_oversubscribe=1
failures=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
trap 'status=$?; [ $status -ne 0 ] && echo "FAIL: install_package stopped (exit status $status)"' EXIT

rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix

echo "=== 1. install into $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in include/qsmpm/core/quasi_static_problem.h \
  include/qsmpm/base/version.h lib/libqsmpm.so bin/qsmpm bin/qsmpm-driver \
  lib/cmake/qsmpm/qsmpmConfig.cmake lib/cmake/qsmpm/qsmpmConfigVersion.cmake \
  lib/cmake/qsmpm/qsmpmTargets.cmake \
  share/qsmpm/examples/block_compression/block_compression.cc \
  share/qsmpm/examples/block_compression/block_compression.prm \
  share/qsmpm/examples/block_compression/CMakeLists.txt \
  share/qsmpm/examples/compact_tension/compact_tension_geometry.h \
  share/qsmpm/examples/polycrystal/odf share/doc/qsmpm/index.md; do
  if [ -e "$prefix/$f" ]; then pass "installed $f"; else fail "not installed: $f"; fi
done

echo "=== 2. configure and build the user project"
cmake -S "$source_dir" -B "$work/app" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >"$work/configure.log"
grep -q "Found qsmpm" "$work/configure.log" &&
  pass "find_package(qsmpm) with CMAKE_PREFIX_PATH" ||
  fail "find_package(qsmpm) did not report the package"
cmake --build "$work/app" -j"${QSMPM_TEST_BUILD_JOBS:-1}" >"$work/build.log" ||
  { cat "$work/build.log"; exit 1; }
pass "user project built"

echo "=== 3. the user program on 2 ranks"
cd "$work/app"
if mpirun -np 2 ./app "$source_dir/kg.prm" >app.out 2>&1; then
  cat app.out
  pass "app on 2 ranks"
else
  cat app.out
  fail "app on 2 ranks"
fi

echo "=== 4. qsmpm --version"
version=$("$prefix/bin/qsmpm" --version)
echo "$version"
if [[ "$version" =~ ^qsmpm\ [0-9]+\.[0-9]+\.[0-9]+\ \(deal\.II\ [0-9.]+\)$ ]]; then
  pass "qsmpm --version"
else
  fail "qsmpm --version printed <$version>"
fi

echo "=== 5. the installed driver with --plugin on 2 ranks"
mkdir -p "$work/driver" && cd "$work/driver"
if mpirun -np 2 "$prefix/bin/qsmpm" --plugin "$work/app/libusermodel.so" \
  "$source_dir/kg.prm" >driver.out 2>&1; then
  pass "qsmpm --plugin libusermodel.so kg.prm"
else
  cat driver.out
  fail "qsmpm --plugin libusermodel.so kg.prm"
fi
csv=output-driver/reactions.csv
if [ -f $csv ]; then
  # The plate (boundary 3) y force at the last step, against
  # E' delta/H W with E' = E/(1-nu^2) = 4G(3K+G)/(3K+4G), delta = 0.01, H =
  # W = 1 (K = 8000, G = 4000 in kg.prm).
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "boundary_3_Fy") c = i }
           END { K = 8000; G = 4000; F = 4*G*(3*K+G)/(3*K+4*G) * 0.01;
                 e = (-$c - F) / F; if (e < 0) e = -e;
                 printf "driver plate force %.12g, analytical %.12g, relative difference %.3g\n", -$c, F, e;
                 exit !(c > 0 && e <= 1e-6) }' $csv &&
    pass "driver plate force = analytical (1e-6)" ||
    fail "driver plate force"
else
  fail "no $csv"
fi
# The plugin's model is in the printed parameters, and only with the plugin.
# (Into files, not into grep -q: with pipefail, grep closing the pipe early
# would fail the pipeline.)
"$prefix/bin/qsmpm" --plugin "$work/app/libusermodel.so" --print-parameters \
  >with-plugin.prm
"$prefix/bin/qsmpm" --print-parameters >without-plugin.prm
if grep -q "subsection K-G elastic" with-plugin.prm &&
  ! grep -q "subsection K-G elastic" without-plugin.prm; then
  pass "--print-parameters lists the plugin's model (only with --plugin)"
else
  fail "--print-parameters and the plugin's model"
fi

echo "=== 6. a missing plugin"
if "$prefix/bin/qsmpm" --plugin "$work/no-such-plugin.so" \
  "$source_dir/kg.prm" >missing.out 2>&1; then
  fail "a missing plugin was accepted"
elif grep -q "no-such-plugin.so" missing.out; then
  pass "a missing plugin stops the driver with: $(head -c 200 missing.out)"
else
  cat missing.out
  fail "the message does not name the missing plugin"
fi

trap - EXIT
if [ $failures -ne 0 ]; then
  echo "install_package: $failures FAILED"
  exit 1
fi
echo "install_package: all PASSED"
