#!/usr/bin/env bash
# Installs what is missing, builds everything and runs every test: core (GoogleTest), Python
# (pytest), command line, studio GUI (Qt Test under Xvfb), then the core tests again under
# AddressSanitizer + UndefinedBehaviorSanitizer. This is the README's test command; .ci/run
# calls it. Builds go to build/ and build-asan/ (ccache makes rebuilds cheap).
set -euo pipefail
cd "$(dirname "$0")/.."

jobs=${THESPIS_JOBS:-$(nproc)}
./scripts/install-deps.sh

export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/ccache}
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-5G}
# Paths inside the checkout count as relative, so a clone elsewhere still hits the cache.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}

echo "== build (Release) =="
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3
cmake --build build -j "$jobs"

echo "== tests =="
# GUI tests need a display: the tests run the studio under Xvfb (xvfb-run is used by ctest).
(cd build && ctest -j "$jobs" --output-on-failure --timeout 600)

echo "== core tests under AddressSanitizer + UndefinedBehaviorSanitizer =="
# Without CPU dispatch, so that these tests also cover the baseline (non-AVX2) code paths. At -O1
# with line tables only (-g1: enough for the sanitizers' stack traces) the core and its tests
# compile in half the time -O2 -g takes; only the core tests are built.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTHESPIS_SANITIZE=address,undefined \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DTHESPIS_BUILD_GUI=OFF -DTHESPIS_BUILD_PYTHON=OFF -DTHESPIS_BUILD_BENCH=OFF -DTHESPIS_CPU_DISPATCH=OFF \
  -DPython_EXECUTABLE=/usr/bin/python3
cmake --build build-asan -j "$jobs" --target thespis_core_tests
# tests/lsan.supp: leaks inside third-party libraries (pocketsphinx's grammar parser) only.
leak_suppressions="$PWD/tests/lsan.supp"
# intercept_tls_get_addr=0: up to GCC 13 the sanitizers' __tls_get_addr hook takes a dynamic TLS
# block at a certain offset in its page for a glibc 2.19 one and records a garbage range, which
# LeakSanitizer's tracer then dies reading at exit ("Tracer caught signal 11", whichever test
# happened to get such a block: google/sanitizers#1322). Our own thread_locals are in the test
# programs' static TLS, which is still scanned.
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions="$leak_suppressions" \
  ctest -j "$jobs" -L core --output-on-failure --timeout 600)

echo "== all tests passed =="
