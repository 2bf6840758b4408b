#!/usr/bin/env python3
"""lddebug_check.py LOG_DIR [RF_HOME]: check glibc LD_DEBUG=libs logs of a bundle run for library
leaks: programs under RF_HOME (default $RF_HOME, else /tmp/rf) must load only RF_HOME libraries and
the host's own programs (sh, cksum, cat, gmsh... started by railfe) none from RF_HOME. Make the logs:
  mkdir /tmp/lddbg && LD_DEBUG=libs LD_DEBUG_OUTPUT=/tmp/lddbg/ld rfmpirun 2 DECK.xml
  python3 lddebug_check.py /tmp/lddbg             # exit 1 if a library crossed over"""
import glob, os, re, sys, collections
if len(sys.argv) < 2: sys.exit(__doc__)
home = (sys.argv[2] if len(sys.argv) > 2 else os.environ.get('RF_HOME', '/tmp/rf')).rstrip('/') + '/'
bad = []; stats = collections.Counter()
for f in sorted(p for p in glob.glob(sys.argv[1] + '/*') if os.path.isfile(p)):
    seg = []
    for line in open(f, errors='replace'):
        m = re.search(r'calling init: (\S+)', line)
        if m: seg.append(m.group(1)); continue
        m = re.search(r'initialize program: (\S+)', line)
        if m:
            prog = m.group(1); bundled = prog.startswith(home)
            stats['bundled programs' if bundled else 'host programs'] += 1
            for lib in seg:
                if lib == '/lib64/ld-linux-x86-64.so.2' and bundled:
                    continue  # the running loader is named after PT_INTERP
                if bundled != lib.startswith(home):
                    bad.append((f, prog, lib))
            stats['libs checked'] += len(seg)
            if bundled: stats['bundle libs'] += len(seg)
            seg = []
print(dict(stats))
for b in bad[:20]: print('LEAK', *b)
print('OK: no library crossed between host programs and the bundle' if not bad else f'{len(bad)} problems')
sys.exit(1 if bad else 0)
