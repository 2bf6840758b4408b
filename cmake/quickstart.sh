#!/usr/bin/env bash
# The two entry points of the README:
#   cmake/quickstart.sh demo   installs what is missing, builds, runs the squeal scene's demo
#                              (inputs/scenes/squeal_demo.xml, about a minute on one core)
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
  "$build/bin/railfe" inputs/scenes/squeal_demo.xml --output demo_results
  python3 regression/charts/contact_force_history.py demo_results/roll_contact_wheel-rail.csv \
    demo_results/contact_forces.png || echo "(no chart: python3 with matplotlib is missing)"
  echo
  echo "Results in demo_results/: contact_forces.png (forces), roll_contact_wheel-rail_patch_*.png"
  echo "(contact patches), roll.exo in ParaView, the CSV files in a spreadsheet."
else
  cd "$build"
  ctest --output-on-failure --parallel "$jobs" --timeout 1200
fi
