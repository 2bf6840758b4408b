#!/usr/bin/env bash
# Builds railfe with AddressSanitizer and UndefinedBehaviorSanitizer in a separate build
# directory and runs every test there (unit tests, verification decks at 1 and 2 ranks,
# bad-input decks). Any sanitizer finding stops the process that made it, so the test fails and
# the finding is in the test's log (build-sanitize/Testing/Temporary/LastTest.log).
# usage: regression/sanitize.sh [BUILD_DIR] [-- CTEST ARGS...]
#   BUILD_DIR   default build-sanitize (beside build/)
#   JOBS        environment: parallel compile jobs (default 2)
#   CTEST ARGS  e.g. -R verify.patch_test or -L unit; default: every test
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build-sanitize}
[[ $# -gt 0 ]] && shift
[[ ${1:-} == -- ]] && shift
jobs=${JOBS:-2}
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

# -O1 -g1: line tables for the stack traces, optimized enough that the explicit decks finish.
start=$(date +%s)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DRAILFE_SANITIZE=ON "${launcher[@]}"
cmake --build "$build" -j "$jobs"
built=$(date +%s)

# detect_leaks=0: Open MPI and its transports (UCX, PMIx) keep allocations to the end of the
# process on purpose, and railfe's own memory is checked by the address checks anyway.
# new_delete_type_mismatch=0: Open MPI's C++ bindings are not instrumented and trip this check.
# halt_on_error/abort_on_error: a finding ends the process with a non-zero status.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:new_delete_type_mismatch=0:halt_on_error=1:abort_on_error=1:detect_stack_use_after_return=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
status=0
(cd "$build" && ctest --output-on-failure "$@") || status=$?
finished=$(date +%s)
echo "sanitize.sh: build $((built - start)) s, tests $((finished - built)) s, ctest status $status"
if grep -l -E 'ERROR: AddressSanitizer|runtime error:' "$build"/Testing/Temporary/LastTest*.log 2>/dev/null; then
  echo "sanitize.sh: sanitizer findings above (search the log for 'runtime error:' and 'AddressSanitizer')"
  status=1
fi
exit $status
