#!/usr/bin/env python3
"""collect.py STAGE_DIR: stage the railfe bundle tree in STAGE_DIR/rf (called by make_bundle.sh).
Copies the repository's build/bin/railfe, Debian's Open MPI launcher (orterun), its MCA and PMIx
plugins (network/GPU ones left out) and the whole shared-library closure from ldd, glibc and
ld-linux-x86-64.so.2 included, plus Open MPI's and PMIx's help/data files."""
import os, re, shutil, subprocess, sys, glob
REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'))
R = os.path.join(sys.argv[1] if len(sys.argv) > 1 else os.environ.get('TMPDIR', '/tmp') + '/rfstage', 'rf')
MPIPLUG = '/usr/lib/x86_64-linux-gnu/openmpi/lib/openmpi3'
PMIXPLUG = '/usr/lib/x86_64-linux-gnu/pmix2/lib/pmix'
SKIP_PLUG = re.compile(r'(ucx|ofi|openib|psm|verbs|monitoring|netlink|cuda|^mca_(atomic|memheap|scoll|spml|sshmem)_)')
if os.path.exists(R): shutil.rmtree(R)
for d in ('bin', 'lib', 'lib/openmpi3', 'lib/pmix', 'share/openmpi', 'share/pmix', 'etc'):
    os.makedirs(f'{R}/{d}')
libs = {}  # soname -> source path
def closure(elf):
    out = subprocess.run(['ldd', elf], capture_output=True, text=True).stdout
    for line in out.splitlines():
        line = line.strip()
        m = re.match(r'(\S+) => (\S+) \(0x', line)
        if m:
            name, path = m.groups()
            if name not in libs: libs[name] = path
        elif 'not found' in line:
            sys.exit(f'unresolved in {elf}: {line}')
        elif line.startswith('/') and 'ld-linux' in line:
            libs['ld-linux-x86-64.so.2'] = line.split()[0]
def copy(src, dst):
    shutil.copy2(os.path.realpath(src), dst)
railfe = f'{REPO}/build/bin/railfe'
if not os.path.isfile(railfe): sys.exit(f'no {railfe}: build railfe first')
copy(railfe, f'{R}/bin/railfe'); closure(railfe)
orterun = os.path.realpath(shutil.which('mpirun'))
copy(orterun, f'{R}/bin/orterun'); closure(orterun)
kept = []
for p in sorted(glob.glob(f'{MPIPLUG}/*.so')):
    b = os.path.basename(p)
    if SKIP_PLUG.search(b): continue
    copy(p, f'{R}/lib/openmpi3/{b}'); closure(p); kept.append(b)
for p in sorted(glob.glob(f'{PMIXPLUG}/*.so')):
    b = os.path.basename(p)
    copy(p, f'{R}/lib/pmix/{b}'); closure(p)
for name, path in sorted(libs.items()):
    copy(path, f'{R}/lib/{name}')
for f in glob.glob('/usr/share/openmpi/help-*.txt') + ['/usr/share/openmpi/amca-param-sets']:
    if os.path.isdir(f): shutil.copytree(f, f'{R}/share/openmpi/{os.path.basename(f)}')
    else: shutil.copy2(f, f'{R}/share/openmpi/')
for f in glob.glob('/usr/lib/x86_64-linux-gnu/pmix2/share/pmix/*'):
    shutil.copy2(f, f'{R}/share/pmix/')
print(f'collect.py: {R}: {len(libs)} libs; {len(kept)} mpi plugins')
