#!/usr/bin/env bash
# The two entry points of the README:
#   cmake/quickstart.sh demo   installs what is missing, builds, runs inputs/demo.xml
#   cmake/quickstart.sh test   installs what is missing, builds, runs every test (what CI runs)
# Environment: BUILD_DIR (default build), JOBS (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
if [[ "$mode" != demo && "$mode" != test ]]; then
  echo "usage: cmake/quickstart.sh demo|test" >&2
  exit 2
fi
build=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}

bash cmake/install-dependencies.sh
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --parallel "$jobs"

if [[ "$mode" == demo ]]; then
  "$build/bin/railfe" inputs/demo.xml --output demo_results
  echo
  echo "Results in demo_results/: open wheel_load.exo in ParaView; the CSV files in a spreadsheet."
else
  cd "$build"
  ctest --output-on-failure --parallel "$jobs" --timeout 1200
fi
