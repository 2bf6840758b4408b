"""Runs one deck and checks railfe's contract on the outcome:
  exit 0  every result file is free of NaN and inf (CSV cells, summary.json, summary.txt, Exodus
          files through ncdump);
  exit 1  the message names the deck file and a parameter path, and no complete-looking result
          file is left;
  exit 2  FAILED.txt is left and no complete-looking result file;
  any other status, a signal or a run past the time limit is a violation.
Returns the list of violations as one-line strings (empty: the contract held)."""

import csv
import json
import math
import os
import re
import shutil
import subprocess

NON_FINITE = re.compile(r"(?<![A-Za-z_])[-+]?(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)
QUOTED = re.compile(r"'([^'\n]+)'")
BOOKKEEPING = ("FAILED.txt", ".railfe-outputs")
NCDUMP = shutil.which("ncdump")
MAX_NCDUMP_BYTES = 20 * 1024 * 1024


def run(command, timeout):
    """Runs railfe; returns (status or None on timeout, combined output)."""
    try:
        process = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 timeout=timeout, start_new_session=True)
        return process.returncode, process.stdout.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as expired:
        output = expired.stdout.decode("utf-8", "replace") if expired.stdout else ""
        return None, output


def _non_finite_csv(path):
    with open(path, newline="", encoding="utf-8", errors="replace") as handle:
        for row_number, row in enumerate(csv.reader(handle), start=1):
            for column, cell in enumerate(row, start=1):
                text = cell.strip()
                try:
                    number = float(text)
                except ValueError:
                    continue
                if not math.isfinite(number):
                    return "row %d column %d is %r" % (row_number, column, text)
    return None


def _non_finite_json(path):
    found = []

    def constant(name):
        found.append(name)
        return 0.0

    with open(path, encoding="utf-8", errors="replace") as handle:
        text = handle.read()
    try:
        json.loads(text, parse_constant=constant,
                   parse_float=lambda s: found.append(s) if not math.isfinite(float(s)) else 0.0)
    except ValueError as error:
        match = NON_FINITE.search(text)
        if match:
            return "not valid JSON (%s) near %r" % (error, text[max(0, match.start() - 40):
                                                               match.end()])
        return "not valid JSON: %s" % error
    return "contains %s" % found[0] if found else None


def _non_finite_text(path):
    with open(path, encoding="utf-8", errors="replace") as handle:
        for line_number, line in enumerate(handle, start=1):
            # The title is the deck's own text, which may well read "nan".
            if line.strip().startswith("title ") or line.strip().startswith("deck "):
                continue
            if NON_FINITE.search(line):
                return "line %d: %s" % (line_number, line.strip()[:120])
    return None


def _non_finite_exodus(path):
    if NCDUMP is None or os.path.getsize(path) > MAX_NCDUMP_BYTES:
        return None
    dump = subprocess.run([NCDUMP, path], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                          timeout=60).stdout.decode("utf-8", "replace")
    data = dump.split("\ndata:", 1)[-1]
    for line in data.splitlines():
        if re.search(r"(?<![A-Za-z_])-?(NaN|Infinity)f?(?![A-Za-z_])", line):
            return "ncdump: %s" % line.strip()[:120]
    return None


def result_files(output):
    found = []
    for directory, _, names in os.walk(output):
        for name in names:
            found.append(os.path.join(directory, name))
    return sorted(found)


def check_results(output):
    """NaN or inf anywhere in the results of a successful run."""
    problems = []
    for path in result_files(output):
        name = os.path.basename(path)
        if name.endswith(".csv"):
            problem = _non_finite_csv(path)
        elif name.endswith(".json"):
            problem = _non_finite_json(path)
        elif name.endswith(".txt"):
            problem = _non_finite_text(path)
        elif name.endswith(".exo") or name.endswith(".e"):
            problem = _non_finite_exodus(path)
        else:
            problem = None
        if problem:
            problems.append("exit 0 but %s: %s" % (os.path.relpath(path, output), problem))
    return problems


def _names_parameter(output, top_level_names):
    """Whether some quoted text in the message is a parameter path of the deck: it starts at one
    of the deck's top-level names (Mesh, Materials, Steps, ...)."""
    for quoted in QUOTED.findall(output):
        if quoted.split("/", 1)[0] in top_level_names:
            return True
    return False


def _complete_looking(output):
    return [os.path.relpath(path, output) for path in result_files(output)
            if not path.endswith(".part") and os.path.basename(path) not in BOOKKEEPING]


def check_outcome(status, output_text, deck_path, output, top_level_names, timeout):
    if status is None:
        return ["no result within %g s (hang or runaway run)" % timeout]
    if status < 0:
        return ["killed by signal %d" % -status]
    if status not in (0, 1, 2):
        return ["exit status %d (only 0, 1, 2 allowed)" % status]
    problems = []
    if status == 0:
        problems += check_results(output) if os.path.isdir(output) else []
        return problems
    if status == 1:
        if os.path.basename(deck_path) not in output_text:
            problems.append("exit 1 but the message does not name the deck file")
        if not _names_parameter(output_text, top_level_names):
            problems.append("exit 1 but the message names no parameter path")
    if status == 2 and not os.path.isfile(os.path.join(output, "FAILED.txt")):
        problems.append("exit 2 but no FAILED.txt in the results directory")
    if os.path.isdir(output):
        left = _complete_looking(output)
        if left:
            problems.append("exit %d but complete-looking files were left: %s"
                            % (status, ", ".join(left[:5])))
    return problems
