#!/usr/bin/python3
"""Benchmark: the contact geometry of the S1002 wheel on the 60E1 rail (Manchester benchmark
profiles). Times the online contact search (from a 0.25 mm table, in the rigid poses of a 0.01 mm
table, both wheels, 40 000 searches), the table lookup (10^6 interpolated starts) and building a
3001-shift table (+-15 mm at 0.01 mm, with the 100-sample check for contact jumps per row).
Targets (issue 5): search <= 20 us per wheel, lookup <= 0.5 us, 3000-shift table <= 1 s.
There is no reference program on this machine (Kalker's CONTACT is not a Debian package), so
the figures are absolute.

Runs the railfe-contact-geometry tool three times and keeps the best of each figure. Writes
docs/data/contact_geometry_benchmark.csv. Run on an idle machine from the repository root:
  /usr/bin/python3 regression/benchmarks/contact_geometry.py [build/bin/railfe-contact-geometry]
"""
import tool_benchmark

if __name__ == "__main__":
    tool_benchmark.main("railfe-contact-geometry", "contact_geometry_benchmark.csv")
