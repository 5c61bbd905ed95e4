#!/usr/bin/env python3
"""grid_error.py REFERENCE.csv RUN.csv: a grid run's error against a converged reference of the
same grid (two `candela run` grid CSVs, same points in the same order; docs/performance.md,
"The error policy at the defaults").

Prints the per-point relative error |E - E_ref| / E_ref as RMS, 95th percentile and maximum; the
reference's and the run's own relative standard errors (RMS: the reference's adds to the RMS in
quadrature); the RMS of the differences in combined standard errors (about 1 or below when the
error bars hold); and the grid mean, minimum and U0 of both."""
import csv
import math
import sys


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r["illuminance_lux"]) for r in rows], [float(r["error_lux"]) for r in rows]


def main():
    ref, ref_se = load(sys.argv[1])
    run, run_se = load(sys.argv[2])
    if len(ref) != len(run):
        sys.exit("the two grids have different numbers of points")
    n = len(ref)
    rel = sorted(abs(a - b) / b for a, b in zip(run, ref))
    rms = math.sqrt(sum(r * r for r in rel) / n)
    p95 = rel[min(n - 1, math.ceil(0.95 * n) - 1)]
    ref_rel = math.sqrt(sum((e / v) ** 2 for e, v in zip(ref_se, ref)) / n)
    run_rel = math.sqrt(sum((e / v) ** 2 for e, v in zip(run_se, run)) / n)
    z = math.sqrt(sum((a - b) ** 2 / (ea * ea + eb * eb) for a, b, ea, eb in zip(run, ref, run_se, ref_se)) / n)
    mean_ref, mean_run = sum(ref) / n, sum(run) / n
    print(f"points {n}: RMS {100 * rms:.2f} %, p95 {100 * p95:.2f} %, max {100 * rel[-1]:.2f} %; "
          f"standard errors (RMS) reference {100 * ref_rel:.2f} %, run {100 * run_rel:.2f} %; "
          f"RMS of differences in combined standard errors {z:.2f}; "
          f"mean {mean_run:.1f} vs {mean_ref:.1f} lx ({100 * (mean_run / mean_ref - 1):+.2f} %), "
          f"min {min(run):.1f} vs {min(ref):.1f} lx, U0 {min(run) / mean_run:.3f} vs {min(ref) / mean_ref:.3f}")


if __name__ == "__main__":
    main()
