# railfe portable bundle: source me (bash or POSIX sh), from the repository root:
#     . .devbundle/setup.sh
# (kept in regression/benchmarks/device/, copied to .devbundle/ by make_bundle.sh there)
# Unpacks .devbundle/rf.tar.xz (railfe + its whole shared-library closure including glibc and
# ld-linux-x86-64.so.2, Debian's Open MPI 4.1.4 mpirun/orterun with its MCA plugins, PMIx)
# into $RF_HOME (default /tmp/rf) and puts $RF_HOME/bin on PATH. Then:
#     rfmpirun NP DECK.xml [--output DIR]     # railfe on NP local ranks (shared memory only)
# Everything runs through the bundled loader, so the host's glibc, MPI and BLAS are never used.
# Extra orterun options: RF_MPIRUN_OPTS="--mca mca_base_verbose 100" rfmpirun 2 ...
# Do not run railfe without rfmpirun (a singleton MPI_Init would look for orted): use rfmpirun 1.

RF_HOME=${RF_HOME:-/tmp/rf}
export RF_HOME
if [ -z "${RF_ARCHIVE:-}" ]; then
  if [ -n "${BASH_VERSION:-}" ] && [ -n "${BASH_SOURCE:-}" ]; then
    RF_ARCHIVE="$(cd "$(dirname "${BASH_SOURCE}")" && pwd)/rf.tar.xz"
  else
    RF_ARCHIVE="$(pwd)/.devbundle/rf.tar.xz"
  fi
fi
_rf_repo=$(cd "$(dirname "$RF_ARCHIVE")/.." 2>/dev/null && pwd)
if [ ! -f "$RF_ARCHIVE" ]; then
  echo "setup.sh: no archive at $RF_ARCHIVE (source me from the repository root or set RF_ARCHIVE)" >&2
  return 1 2>/dev/null || exit 1
fi
_rf_sum=$(cksum < "$RF_ARCHIVE")
if [ ! -x "$RF_HOME/bin/rfmpirun" ] || [ "$(cat "$RF_HOME/.archive-cksum" 2>/dev/null)" != "$_rf_sum" ]; then
  echo "setup.sh: unpacking $RF_ARCHIVE into $RF_HOME" >&2
  rm -rf "$RF_HOME" && mkdir -p "$RF_HOME"
  if command -v xz >/dev/null 2>&1; then
    xz -dc "$RF_ARCHIVE" | tar -x -f - -C "$RF_HOME" --strip-components=1
  else  # no xz binary: Python's lzma module reads the same archive
    python3 - "$RF_ARCHIVE" "$RF_HOME" <<'PYEOF'
import sys, tarfile
with tarfile.open(sys.argv[1], "r:xz") as t:
    for m in t.getmembers():
        m.name = m.name.split("/", 1)[1] if "/" in m.name else "."
    t.extractall(sys.argv[2])
PYEOF
  fi || { echo "setup.sh: unpacking failed" >&2; return 1 2>/dev/null || exit 1; }
  echo "$_rf_sum" > "$RF_HOME/.archive-cksum"
fi
unset _rf_sum
# railfe has the build's source path compiled in: /work/main/inputs/profiles (wheel/rail profiles),
# /work/main/inputs/kalker, /work/main/regression/charts. Point /work/main at this repository.
if [ "$_rf_repo" != /work/main ] && [ ! -f /work/main/inputs/profiles/MBench_S1002_v3.prw ]; then
  if [ -L /work/main ] || [ ! -e /work/main ] || rmdir /work/main 2>/dev/null; then
    mkdir -p /work && ln -sfn "$_rf_repo" /work/main && echo "setup.sh: /work/main -> $_rf_repo" >&2
  else
    echo "setup.sh: WARNING /work/main exists and is not this repository: railfe will not find its profiles" >&2
  fi
fi
unset _rf_repo
case ":$PATH:" in *":$RF_HOME/bin:"*) ;; *) PATH="$RF_HOME/bin:$PATH"; export PATH ;; esac
rfmpirun() { "$RF_HOME/bin/rfmpirun" "$@"; }
if ! "$RF_HOME/bin/rfmpirun" 1 --version; then
  echo "setup.sh: the bundled railfe does not start (try RF_MPIRUN_OPTS='--mca mca_base_verbose 100')" >&2
fi
