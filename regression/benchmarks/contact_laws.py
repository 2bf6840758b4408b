#!/usr/bin/python3
"""Benchmark: the contact-mechanics theories on the issue's Hertz patch (0.46 m wheel on a 0.30 m
crown, 100 kN, steel, mu 0.3), mean time per evaluation on one core over the six partial-slip
cases of regression/studies/contact_speed_accuracy.py (xi, eta 1e-3 and 3e-3; spin 0.5 and
2 /m). Kalker's linear forces (coefficients given; their lookup timed apart), Polach, FASTSIM
at 20 x 20 (forces only), the creep-force table, and the exact solver at 40 x 40: its normal
problem (kernels, Polonsky-Keer from Hertz's pressure) plus one tangential solve, with the
iteration counts. Targets (issue 6): linear <= 0.1 us, FASTSIM <= 5 us, table <= 1 us, exact
<= 50 ms.

Issue 14 adds the case timed against Kalker's CONTACT: a Hertz patch with a/b = 0.5 (a 5 mm,
b 10 mm, 100 kN, steel), Coulomb friction mu 0.3, four longitudinal creepages (1e-3 to 4e-3), on
CONTACT's grids 24 x 22, 48 x 44 and 96 x 88, in processor time (the machine is shared): one
normal solve (kernels included) and the four tangential solves, with their forces. CONTACT
cannot run here: its normal solve is the issue's measurement (1, 8, 25 ms), its tangential solve
4 x railfe's before issue 14 (the issue's ratio), and the target is a third of its whole case.

Runs the railfe-contact-mechanics tool three times and keeps the best of each figure. Writes
docs/data/contact_laws_benchmark.csv. Run on an idle machine from the repository root:
  /usr/bin/python3 regression/benchmarks/contact_laws.py [build/bin/railfe-contact-mechanics]
"""
import tool_benchmark

if __name__ == "__main__":
    tool_benchmark.main("railfe-contact-mechanics", "contact_laws_benchmark.csv")
