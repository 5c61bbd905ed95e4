#!/usr/bin/env python3
"""t2a_table.py RADIANCE_WORKDIR CANDELA_WORKDIR: the time-to-accuracy table against Radiance
(docs/performance.md, "Time to accuracy against Radiance"; issue 37) from the files that
scripts/radiance_t2a.sh and scripts/candela_t2a.sh --refs wrote. Never run by CI.

The reference of office and sunny is the mean of candela's two converged path runs (seeds 1001
and 1002); its own noise (the RMS of its relative standard errors) is printed, and the RMS errors
are given both as measured and with that noise taken out in quadrature. The sphere's reference is
exact: E = pi L r^2 (1/d^2 + rho/(1 - rho)) (the lamp's direct light at the sensor plus the wall's
uniform interreflected light; the 2 cm lamp's shadow on the wall, 4e-4, is left out).

Radiance runs with "-dj .7" (files <case>dj-S<k>) are listed apart (the sun's disk jittered: soft
shadows). "CPU s to reach RMS x" interpolates log CPU linearly in log RMS between the cheapest run at or
below x and the most expensive cheaper run above it; "-" when no run reaches it."""
import math
import os
import sys

rad_dir, can_dir = sys.argv[1], sys.argv[2]


def load(path):
    with open(path) as f:
        return [float(x) for x in f.read().split()]


def cpu(path):
    with open(path) as f:
        return float(f.read().split()[0])


def errors(run, ref, noise):
    rel = sorted(abs(a - b) / b for a, b in zip(run, ref))
    n = len(rel)
    rms = math.sqrt(sum(r * r for r in rel) / n)
    p95 = rel[min(n - 1, math.ceil(0.95 * n) - 1)]
    mean = sum(run) / n / (sum(ref) / n) - 1
    return rms, math.sqrt(max(0.0, rms * rms - noise * noise)), p95, mean


def reach(runs, target):
    """runs: [(cpu, rms)]; CPU at which the RMS first reaches target (log-log interpolation)."""
    runs = sorted(runs)
    for i, (c, e) in enumerate(runs):
        if e <= target:
            above = [(c0, e0) for c0, e0 in runs[:i] if e0 > target]
            if not above:
                return c, "<="
            c0, e0 = above[-1]
            t = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e))
            return math.exp(math.log(c0) + t * (math.log(c) - math.log(c0))), ""
    return None, ""


for case in ("office", "sunny", "sphere"):
    if not os.path.exists(os.path.join(can_dir, f"{case}-normal.lux")):
        continue
    if case == "sphere":
        L, r, d, rho = 1000.0 * 179.0, 0.02, 0.999, 0.5
        e = math.pi * L * r * r * (1 / (d * d) + rho / (1 - rho))
        ref = [e] * 64
        noise = 0.0
        print(f"\n## sphere: reference exact {e:.2f} lx at all 64 points")
    else:
        seeds = [sd for sd in (1001, 1002) if os.path.exists(os.path.join(can_dir, f"{case}-ref{sd}.cpu"))]
        vals = [load(os.path.join(can_dir, f"{case}-ref{sd}.lux")) for sd in seeds]
        ses = [load(os.path.join(can_dir, f"{case}-ref{sd}.se")) for sd in seeds]
        k = len(seeds)
        ref = [sum(v[i] for v in vals) / k for i in range(len(vals[0]))]
        n = len(ref)
        noise = math.sqrt(sum((math.sqrt(sum(se[i] ** 2 for se in ses)) / k / ref[i]) ** 2 for i in range(n)) / n)
        cref = sum(cpu(os.path.join(can_dir, f"{case}-ref{sd}.cpu")) for sd in seeds)
        line = (f"\n## {case}: reference = mean of seeds {' and '.join(map(str, seeds))} ({n} points, {cref:.1f} CPU s "
                f"together, mean {sum(ref) / n:.2f} lx); the reference's noise {100 * noise:.2f} % RMS")
        if k == 2:
            agree = math.sqrt(sum(((x - y) / m) ** 2 for x, y, m in zip(vals[0], vals[1], ref)) / n)
            own = math.sqrt(sum((math.sqrt(u * u + v * v) / m) ** 2 for u, v, m in zip(ses[0], ses[1], ref)) / n)
            line += f"; the seeds differ by RMS {100 * agree:.2f} % (their combined standard errors: {100 * own:.2f} %)"
        print(line)
    rows = {"Radiance": [], "Radiance -dj .7": [], "candela": []}
    print("| tool | run | CPU s | RMS | RMS (noise out) | p95 | mean vs ref |")
    print("|---|---|---|---|---|---|---|")
    for prefix, tool in ((case, "Radiance"), (case + "dj", "Radiance -dj .7")):
        for k in (1, 2, 3):
            p = os.path.join(rad_dir, f"{prefix}-S{k}.lux")
            if os.path.exists(p) and os.path.exists(os.path.join(rad_dir, f"{prefix}-S{k}.cpu")):
                c = cpu(os.path.join(rad_dir, f"{prefix}-S{k}.cpu"))
                rms, rmsc, p95, mean = errors(load(p), ref, noise)
                rows[tool].append((c, rmsc))
                print(f"| {tool} | S{k} | {c:.2f} | {100 * rms:.2f} % | {100 * rmsc:.2f} % | {100 * p95:.2f} % | {100 * mean:+.2f} % |")
    for tag in ("draft", "normal-te2", "normal-te0", "normal", "high"):
        p = os.path.join(can_dir, f"{case}-{tag}.lux")
        if os.path.exists(p):
            c = cpu(os.path.join(can_dir, f"{case}-{tag}.cpu"))
            rms, rmsc, p95, mean = errors(load(p), ref, noise)
            rows["candela"].append((c, rmsc))
            print(f"| candela | {tag} | {c:.2f} | {100 * rms:.2f} % | {100 * rmsc:.2f} % | {100 * p95:.2f} % | {100 * mean:+.2f} % |")
    for tool, runs in rows.items():
        if not runs:
            continue
        cells = []
        for target in (0.05, 0.02, 0.01):
            c, how = reach(runs, target)
            cells.append("-" if c is None else f"{how}{c:.1f}")
        print(f"{case} {tool}: CPU s to reach RMS 5 % / 2 % / 1 %: {' / '.join(cells)}")
