#!/usr/bin/env bash
# The node-to-segment search against the size of the master surface (issue 15, "Benchmark"):
# BucketSearch::rebuild per face and find_contact_point per slave query on tread-like patches of
# 1e3, 1e4 and 1e5 faces of 1 mm (contact/tools/contact_search_benchmark.cpp). Medians of 7
# batches; on a shared machine run it more than once and compare.
#   bash regression/benchmarks/contact_search_benchmark.sh [BUILD_DIR] [FACES ...]
# Writes docs/data/contact_search_benchmark.csv.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
shift || true
cmake --build "$build" --target railfe-contact-search-benchmark >/dev/null
mkdir -p "$root/docs/data"
"$build/bin/railfe-contact-search-benchmark" "$root/docs/data/contact_search_benchmark.csv" "$@"
cat "$root/docs/data/contact_search_benchmark.csv"
