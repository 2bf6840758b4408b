#!/usr/bin/env python3
"""prep_deck.py OUT_DIR: write the device benchmark decks into OUT_DIR (make_bundle.sh: .devbundle/)
from the repository's generator regression/scenes/make_squeal_decks.py, then edit them as text
(the header comment is kept and gets a BENCHMARK VARIANT note):
  bench_mid4mm_case1.xml  case 1, every refined size 4 mm, 1.5 ms; no "modes" step, no preload
  bench_full_case1.xml    case 1 as shipped (1 mm), 0.3 ms; no "modes" step, no preload
  true_full_case1.xml     case 1 as shipped, 0.3 ms; no "modes" step, the statics preload kept
The preload (CHOLMOD on rank 0) and the modes step take most of a device budget at full scale."""
import os, re, subprocess, sys, tempfile
REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'))
GEN = os.path.join(REPO, 'regression', 'scenes', 'make_squeal_decks.py')

def generate(*args):
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([sys.executable, GEN, '--case', '1', *args, '--output', d + '/deck.xml'], check=True)
        return open(d + '/deck.xml').read()

def drop_list(lines, name):
    i = next(k for k, l in enumerate(lines) if l.strip() == f'<ParameterList name="{name}">')
    ind = lines[i][:len(lines[i]) - len(lines[i].lstrip())]
    j = next(k for k in range(i + 1, len(lines)) if lines[k] == ind + '</ParameterList>')
    del lines[i:j + 1]

def edit(txt, note, end_time=None, drop_modes=True, drop_preload=False):
    lines = txt.split('\n')
    if drop_modes: drop_list(lines, 'modes')
    if drop_preload:
        drop_list(lines, 'preload')
        lines = [l for l in lines if '<Parameter name="Start from"' not in l]
    txt = '\n'.join(lines)
    if end_time:
        txt, n = re.subn(r'(<Parameter name="End time" type="double" value=")[^"]*(")', r'\g<1>' + end_time + r'\2', txt)
        assert n == 1, n
        def fix(m):  # patch snapshots only at times inside the run (else at its end)
            ts = [t for t in m.group(2).strip('{}').split(',') if float(t) <= float(end_time) + 1e-15]
            return m.group(1) + '{' + (', '.join(t.strip() for t in ts) or end_time) + '}' + m.group(3)
        txt = re.sub(r'(<Parameter name="Patch times" type="Array\(double\)" value=")([^"]*)(")', fix, txt)
    return txt.replace('-->', '  ' + note + '\n-->', 1)

def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(REPO, '.devbundle')
    os.makedirs(out, exist_ok=True)
    full = generate()
    mid = generate('--zone-size', '0.004', '--head-size', '0.004', '--arc-size', '0.004',
                   '--tread-size', '0.004', '--end-time', '0.0015')
    decks = {
        'bench_mid4mm_case1.xml': edit(mid, 'BENCHMARK VARIANT (.devbundle, not a shipped deck): every refined size 4 mm (zone, head, arc, tread), step "modes" and the statics preload dropped (explicit from the placed position), 1.5 ms. Written by make_squeal_decks.py (case 1, zone, head, arc and tread size 0.004, end time 0.0015), then edited.', drop_preload=True),
        'bench_full_case1.xml': edit(full, 'BENCHMARK VARIANT (.devbundle): squeal_case1.xml with step "modes" and the statics preload dropped (CHOLMOD on rank 0 would take most of the time budget), End time 0.3 ms.', end_time='3e-4', drop_preload=True),
        'true_full_case1.xml': edit(full, 'BENCHMARK VARIANT (.devbundle): squeal_case1.xml with step "modes" dropped, End time 0.3 ms; the preload (CHOLMOD on rank 0) is kept.', end_time='3e-4'),
    }
    for name, txt in decks.items():
        open(os.path.join(out, name), 'w').write(txt)
        print(f'prep_deck.py: wrote {os.path.join(out, name)}')

if __name__ == '__main__':
    main()
