#!/usr/bin/env python3
"""Deck fuzzer: mutates the shipped decks (a fixed seed makes every deck reproducible) and runs
railfe on each, checking its contract on the outcome (see checks.py). Prints every violation
with the deck, its mutations and what went wrong, keeps the offending decks, and exits 1 when
there was any.

  fuzz_decks.py --railfe build/bin/railfe [--seed 14] [--count 200] [--jobs 2] [--timeout 20]
                [--work DIR] [--only INDEX]

Deck INDEX of a seed is always the same deck: --only INDEX rebuilds and reruns just that one.
The unmutated (reduced) base decks run first and must exit 0 with clean results.
"""

import argparse
import collections
import concurrent.futures
import os
import random
import re
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import checks  # noqa: E402
import decks  # noqa: E402
import mutations  # noqa: E402

SECTION_NAMES = {"Title", "Mesh", "Materials", "Output", "Steps"}


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    source_root = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
    parser.add_argument("--railfe", required=True, help="the railfe executable")
    parser.add_argument("--source", default=source_root, help="railfe's source root")
    parser.add_argument("--seed", type=int, default=14)
    parser.add_argument("--count", type=int, default=200, help="mutated decks to run")
    parser.add_argument("--jobs", type=int, default=2, help="railfe runs at a time")
    parser.add_argument("--timeout", type=float, default=20, help="seconds per run")
    parser.add_argument("--work", default="fuzz_work", help="decks, results and report")
    parser.add_argument("--only", type=int, default=None, help="run just this deck index")
    parser.add_argument("--skip-base", action="store_true", help="do not run the base decks")
    return parser.parse_args()


class Case:
    """One deck to run: a base deck (mutations empty) or a mutated one."""

    def __init__(self, label, base, root, mutations_done):
        self.label = label
        self.base = base
        self.root = root
        self.mutations = mutations_done
        self.status = None
        self.problems = []
        self.output_text = ""
        self.seconds = 0.0


def make_case(index, seed, bases):
    rng = random.Random("%d:%d" % (seed, index))
    base = rng.choice(bases)
    root = base.copy()
    done = mutations.mutate(root, rng, rng.choices([1, 2, 3], [6, 3, 1])[0])
    return Case("%05d" % index, base, root, done)


def run_case(case, arguments):
    deck_path = os.path.join(arguments.work, "decks", case.label + ".xml")
    output = os.path.join(arguments.work, "results", case.label)
    header = ["railfe fuzz deck %s (seed %d) from %s" % (case.label, arguments.seed,
                                                         case.base.name)]
    header += ["mutation: " + text for text in case.mutations] or ["unmutated (reduced) base"]
    decks.write_deck(case.root, deck_path, header)
    shutil.rmtree(output, ignore_errors=True)
    started = time.monotonic()
    case.status, case.output_text = checks.run(
        [arguments.railfe, deck_path, "--output", output, "--quiet"], arguments.timeout)
    case.seconds = time.monotonic() - started
    top_level = SECTION_NAMES | {child.get("name") for child in case.root}
    top_level |= {child.get("name") for child in case.base.root}
    case.problems = checks.check_outcome(case.status, case.output_text, deck_path, output,
                                         top_level, arguments.timeout)
    if case.status == 0:
        case.problems += ["exit 0 although %s = %s (NaN, inf or hexadecimal: must be refused)"
                          % item for item in decks.refusable_numbers(case.root)]
    if not case.mutations and case.status != 0:
        case.problems.append("the unmutated base deck must exit 0 (exit %s)" % case.status)
    if not case.problems:
        os.remove(deck_path)
        shutil.rmtree(output, ignore_errors=True)
    return case


def describe(case, arguments):
    lines = ["VIOLATION deck %s (seed %d, base %s): %s"
             % (case.label, arguments.seed, case.base.name,
                os.path.join(arguments.work, "decks", case.label + ".xml"))]
    lines += ["  mutation: " + text for text in case.mutations] or ["  unmutated base deck"]
    lines += ["  problem:  " + problem for problem in case.problems]
    tail = [line for line in case.output_text.strip().splitlines() if line.strip()][-3:]
    lines += ["  output:   " + line[:300] for line in tail]
    return "\n".join(lines)


def main():
    arguments = parse_arguments()
    arguments.work = os.path.abspath(arguments.work)
    arguments.railfe = os.path.abspath(arguments.railfe)
    for sub in ("decks", "results"):
        os.makedirs(os.path.join(arguments.work, sub), exist_ok=True)
    bases = decks.load_base_decks(arguments.source)

    cases = []
    if not arguments.skip_base and arguments.only is None:
        cases += [Case("base%02d" % i, base, base.copy(), []) for i, base in enumerate(bases)]
    indices = [arguments.only] if arguments.only is not None else range(arguments.count)
    cases += [make_case(index, arguments.seed, bases) for index in indices]

    started = time.monotonic()
    statuses = {}
    violations = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=arguments.jobs) as pool:
        for case in pool.map(lambda c: run_case(c, arguments), cases):
            key = "timeout" if case.status is None else str(case.status)
            statuses[key] = statuses.get(key, 0) + 1
            if case.problems:
                violations.append(case)
                print(describe(case, arguments), flush=True)

    elapsed = time.monotonic() - started
    # The same problem from many decks (numbers and deck names blanked) counted once, so a new
    # kind of violation stands out.
    kinds = collections.Counter(
        re.sub(r"'[^']*'|/\S+|(?<![A-Za-z_])[-+]?\d[\d.eE+-]*", "#", problem) for case in violations
        for problem in case.problems)
    slowest = sorted(cases, key=lambda c: -c.seconds)[:3]
    summary = ["fuzz: seed %d, %d decks (%d base) in %.0f s; exit statuses %s"
               % (arguments.seed, len(cases), sum(1 for c in cases if not c.mutations), elapsed,
                  ", ".join("%s: %d" % item for item in sorted(statuses.items()))),
               "fuzz: slowest %s" % ", ".join("%s %.1f s" % (c.label, c.seconds)
                                              for c in slowest),
               ] + ["fuzz: %5d x %s" % (n, kind) for kind, n in kinds.most_common()] + [
               "fuzz: %d decks broke the contract%s" % (
                   len(violations), " (kept in %s/decks)" % arguments.work if violations else "")]
    with open(os.path.join(arguments.work, "report.txt"), "w", encoding="utf-8") as report:
        report.write("\n\n".join(describe(c, arguments) for c in violations))
        report.write("\n" + "\n".join(summary) + "\n")
    print("\n".join(summary))
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
