#!/usr/bin/python3
"""Modal runs on a small clamped bar (10 x 1 x 1 hex8, 1 x 0.1 x 0.1 m steel: 132 DOFs, 12 fixed,
120 free) that used to go wrong without a word:

  many-modes  100 modes, far more than a third of the free DOFs: railfe used to build a Krylov
              space larger than the free DOFs and hang. Now it must finish (under a timeout) and
              its 100 frequencies must match LAPACK's dense generalized eigensolver (SciPy's eigh)
              on the same K and M, reduced to the free DOFs, to 1e-8.
  empty-band  a Frequency band below the first mode (1 to 2 Hz; the first bending mode is near
              83 Hz): exit 0 with an empty CSV, but a warning line on the terminal and in
              summary.txt naming the band.

usage: modal_small_models.py RAILFE WORKDIR [MPIEXEC ARGS...]   (runs on 1 and 2 ranks)
"""
import csv
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import scipy.io
import scipy.linalg

TIMEOUT_S = 60


def bar_deck(step_parameters):
    return f"""<ParameterList name="railfe">
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="box"/>
    <ParameterList name="Box">
      <Parameter name="Lengths" type="Array(double)" value="{{1.0, 0.1, 0.1}}"/>
      <Parameter name="Elements" type="Array(int)" value="{{10, 1, 1}}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="steel">
      <Parameter name="Young's modulus" type="double" value="210e9"/>
      <Parameter name="Poisson's ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="7850"/>
      <Parameter name="Blocks" type="Array(string)" value="{{block_1}}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Steps">
    <ParameterList name="modes">
      <Parameter name="Module" type="string" value="modal"/>
      <Parameter name="Exodus" type="bool" value="false"/>
{step_parameters}
      <ParameterList name="Supports">
        <ParameterList name="clamp"><Parameter name="Node set" type="string" value="xmin"/></ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def run(railfe, mpiexec, ranks, workdir, name, step_parameters):
    directory = os.path.join(workdir, f"{name}_np{ranks}")
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    deck = os.path.join(directory, "deck.xml")
    with open(deck, "w") as out:
        out.write(bar_deck(step_parameters))
    results = os.path.join(directory, "results")
    command = mpiexec + ["-np", str(ranks), railfe, deck, "--output", results, "--quiet"]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None, "", results
    return done.returncode, done.stdout + done.stderr, results


def many_modes(railfe, mpiexec, ranks, workdir):
    status, log, results = run(railfe, mpiexec, ranks, workdir, "many_modes",
                               '      <Parameter name="Modes" type="int" value="100"/>\n'
                               '      <Parameter name="Export matrices" type="bool" value="true"/>')
    if status is None:
        return [f"many-modes np{ranks}: still running after {TIMEOUT_S} s (the hang is back)"]
    if status != 0:
        return [f"many-modes np{ranks}: exit {status}\n{log}"]
    with open(os.path.join(results, "modes_modes.csv")) as handle:
        computed = np.array([float(row["frequency_hz"]) for row in csv.DictReader(handle)])
    K = scipy.io.mmread(os.path.join(results, "modes_K.mtx")).toarray()
    M = scipy.io.mmread(os.path.join(results, "modes_M.mtx")).toarray()
    free = np.diag(M) > 0  # fixed DOFs have no mass rows
    values = scipy.linalg.eigh(K[np.ix_(free, free)], M[np.ix_(free, free)], eigvals_only=True)
    reference = np.sqrt(values[:len(computed)]) / (2 * math.pi)
    problems = []
    if np.count_nonzero(free) != 120:
        problems.append(f"many-modes np{ranks}: {np.count_nonzero(free)} free DOFs, expected 120")
    if len(computed) != 100:
        problems.append(f"many-modes np{ranks}: {len(computed)} modes written, expected 100")
    else:
        worst = np.max(np.abs(computed - reference) / reference)
        print(f"many-modes np{ranks}: 100 modes, {reference[0]:.3f} to {reference[-1]:.1f} Hz, "
              f"largest relative difference to LAPACK {worst:.2e}")
        if not worst <= 1e-8:
            problems.append(f"many-modes np{ranks}: differs from LAPACK by {worst:.2e}")
    return problems


def empty_band(railfe, mpiexec, ranks, workdir):
    status, log, results = run(railfe, mpiexec, ranks, workdir, "empty_band",
                               '      <Parameter name="Frequency band" type="Array(double)" '
                               'value="{1, 2}"/>')
    if status != 0:
        return [f"empty-band np{ranks}: exit {status}\n{log}"]
    problems = []
    warning = "no modes in [1, 2] Hz"
    if log.count("railfe: warning: step 'modes': " + warning) != 1:
        problems.append(f"empty-band np{ranks}: the terminal lacks one '{warning}' line:\n{log}")
    with open(os.path.join(results, "summary.txt")) as handle:
        if warning not in handle.read():
            problems.append(f"empty-band np{ranks}: summary.txt lacks '{warning}'")
    print(f"empty-band np{ranks}: exit 0 with the warning on the terminal and in the summary")
    return problems


def main():
    railfe, workdir, mpiexec = sys.argv[1], sys.argv[2], sys.argv[3:] or ["mpirun"]
    problems = []
    for ranks in (1, 2):
        problems += many_modes(railfe, mpiexec, ranks, workdir)
        problems += empty_band(railfe, mpiexec, ranks, workdir)
    for problem in problems:
        print("FAIL:", problem)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
