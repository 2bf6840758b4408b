#!/bin/bash
# Build the portable railfe bundle for the device machine (see README.md here): stages the tree in
# ${TMPDIR:-/tmp}/rfstage/rf and writes <repo>/.devbundle/ (git-ignored): rf.tar.xz, setup.sh,
# device_run.sh and the benchmark decks. About 4 min on one core, mostly xz:
#   nice -n 10 bash regression/benchmarks/device/make_bundle.sh
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$HERE/../../.." && pwd)
S=${TMPDIR:-/tmp}/rfstage
R=$S/rf
B=$REPO/.devbundle
mkdir -p "$S" "$B"
EXCL=$(git -C "$REPO" rev-parse --git-path info/exclude 2>/dev/null || echo .git/info/exclude)
case "$EXCL" in /*) ;; *) EXCL=$REPO/$EXCL ;; esac
if ! grep -qxF '/.devbundle/' "$EXCL" 2>/dev/null; then
  mkdir -p "$(dirname "$EXCL")" && echo '/.devbundle/' >> "$EXCL" && echo "make_bundle.sh: /.devbundle/ added to $EXCL"
fi

# 1. railfe, its library closure (glibc + ld.so too), orterun, MCA/PMIx plugins, help files
python3 "$HERE/collect.py" "$S"
install -m 644 "$HERE/rfenv.sh" "$R/bin/"
install -m 755 "$HERE/rfmpirun" "$HERE/railfe-rank" "$HERE/gmsh" "$R/bin/"
install -m 644 "$HERE/openmpi-mca-params.conf" "$R/etc/"
tar -xJf "$HERE/gmsh-cache.tar.xz" -C "$R/share"
strip --strip-unneeded "$R/bin/railfe"

# 2. the benchmark decks, from regression/scenes/make_squeal_decks.py
python3 "$HERE/prep_deck.py" "$B"

# 3. the gmsh stand-in's cache must hold the decks' section meshes: run the host railfe on each
#    mesh size with the stand-in first on PATH (a miss is meshed by /usr/bin/gmsh and recorded),
#    stop it once both sections (rail, wheel) are meshed
C=$R/share/gmsh-cache
nlog() { if [ -f "$C/log" ]; then wc -l < "$C/log"; else echo 0; fi; }
rm -f "$C/log"
for deck in bench_mid4mm_case1.xml bench_full_case1.xml; do  # true_full has bench_full's mesh
  rm -rf "$S/meshcheck"
  n0=$(nlog)
  env RF_HOME="$R" RF_GMSH_RECORD=1 PATH="$R/bin:/usr/bin:/bin" OMP_NUM_THREADS=1 \
    timeout 120 "$REPO/build/bin/railfe" "$B/$deck" --output "$S/meshcheck" > "$S/meshcheck.log" 2>&1 &
  pid=$!
  for _ in $(seq 240); do
    [ $(( $(nlog) - n0 )) -ge 2 ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.5
  done
  kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true
  if [ $(( $(nlog) - n0 )) -lt 2 ]; then
    echo "make_bundle.sh: railfe did not mesh $deck's sections (see $S/meshcheck.log)" >&2; exit 1
  fi
done
rm -rf "$S/meshcheck"
echo "make_bundle.sh: section meshes: $(sort "$C/log" | uniq -c | tr '\n' ' ')"
if grep -q recorded "$C/log"; then
  echo "make_bundle.sh: NOTE new meshes recorded into the bundle; to keep them in the repository:"
  echo "  (cd $R/share && tar --sort=name --owner=0 --group=0 --numeric-owner --mtime=@0 -cf - --exclude=log gmsh-cache | xz -9e -T1) > $HERE/gmsh-cache.tar.xz"
fi
rm -f "$C/log"

# 4. the bundle starts in a clean environment (bundled loader, OPAL_*/PMIX_* relocation)
env -i PATH=/usr/bin:/bin RF_HOME="$R" "$R/bin/rfmpirun" 1 --version

# 5. archive: BCJ x86 filter + 256 MiB dictionary keep it near 43 MiB (the device tool carries 64 MiB)
tar -C "$S" --sort=name --owner=0 --group=0 --numeric-owner -cf - rf |
  xz --x86 --lzma2=preset=9e,dict=256MiB -T1 > "$S/rf.tar.xz.new"
xz -t "$S/rf.tar.xz.new"
mv "$S/rf.tar.xz.new" "$B/rf.tar.xz"
install -m 644 "$HERE/setup.sh" "$B/setup.sh"
install -m 755 "$HERE/device_run.sh" "$B/device_run.sh"
size=$(du -cb "$B" | tail -1 | cut -f1)
ls -l "$B"
echo "make_bundle.sh: .devbundle is $size bytes (the device tool's carry limit: 67108864)"
[ "$size" -lt 64000000 ] || { echo "make_bundle.sh: WARNING .devbundle is too big to carry" >&2; exit 1; }
