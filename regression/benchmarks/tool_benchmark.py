"""Shared by the benchmark scripts whose figures come from a study tool's `benchmark` mode: runs
`TOOL benchmark OUT.csv` (rows quantity,value,unit,target) several times, keeps the best value of
each timed quantity (unit us, ms or s; counts keep the last run's), and writes the figures with
whether each meets its target."""
import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def best_of_runs(tool, out, runs=3):
    """Runs the tool's benchmark `runs` times and writes the best figures to `out` (CSV)."""
    best = {}
    with tempfile.TemporaryDirectory() as work:
        for run in range(runs):
            path = os.path.join(work, f"run{run}.csv")
            subprocess.run([tool, "benchmark", path], check=True, stdout=subprocess.DEVNULL)
            with open(path) as f:
                for row in csv.DictReader(f):
                    value = float(row["value"])
                    key = row["quantity"]
                    timed = row["unit"] in ("us", "ms", "s")
                    if key not in best or not timed or value < float(best[key]["value"]):
                        best[key] = dict(row, value=value)
    with open(out, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["quantity", "value", "unit", "target", "within_target"])
        for key, row in best.items():
            within = "" if not row["target"] else ("yes" if row["value"] <= float(row["target"]) else "NO")
            writer.writerow([key, f"{row['value']:.4g}", row["unit"], row["target"], within])
            print(f"{key:40s} {row['value']:10.4g} {row['unit']:3s} target {row['target'] or '-':>4s} {within}")
    print("wrote", out)


def main(tool_name, csv_name):
    """Command line of a benchmark script: `[TOOL]` (default build/bin/<tool_name>), writing
    docs/data/<csv_name>."""
    tool = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", tool_name)
    best_of_runs(tool, os.path.join(ROOT, "docs", "data", csv_name))
