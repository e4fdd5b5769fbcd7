#!/usr/bin/python3
"""Throughput of the Python package (docs/python.md): eval, pdf and sample of registry materials
on 10^6 directions per call, and the test kit on a numpy BSDF (the replay, docs/python.md, "The
kit on any object") beside the same kit on a registry material.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_materials.py [--rows N]
        [--repeats R] [--check-samples S] [--threads T] [--json FILE]

Each timing is the best of R runs (wall clock, all cores unless --threads). The numbers are
what a user pays per call from Python, the array checks at the boundary included.
"""
import argparse
import json
import pathlib
import sys
import time

import numpy as np

import scatterlab as sl

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "tests" / "python"))
from numpy_bsdfs import PhongLobe  # noqa: E402  (the tests' numpy lobe, as a user writes one)

MATERIALS = {
    "lambertian": {"type": "lambertian"},
    "conductor (GGX)": {"type": "conductor", "alpha": 0.2},
    "rough-plastic": {"type": "rough-plastic"},
    "dielectric (rough)": {"type": "rough-dielectric", "alpha": 0.2},
}


def best_of(repeats, work):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rows", type=int, default=10**6, help="directions per call (default 10^6)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per timing; the best counts")
    parser.add_argument("--check-samples", type=int, default=10**6, help="samples per chi-square test of the kit")
    parser.add_argument("--threads", type=int, default=0, help="cores for the kit (0: all)")
    parser.add_argument("--json", help="also write the results to this file")
    args = parser.parse_args()

    rng = np.random.default_rng(7)
    n = args.rows
    theta = np.arccos(rng.uniform(0.05, 1.0, size=(2, n)))
    phi = rng.uniform(0, 2 * np.pi, size=(2, n))
    wi, wo = (np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=1) for t, p in zip(theta, phi))
    u_lobe, u = rng.uniform(size=n), rng.uniform(size=(n, 2))

    results = {"rows": n, "materials": {}, "check": {}}
    for name, spec in MATERIALS.items():
        m = sl.material(spec)
        row = {"eval_s": best_of(args.repeats, lambda: m.eval(wi, wo)),
               "pdf_s": best_of(args.repeats, lambda: m.pdf(wi, wo)),
               "sample_s": best_of(args.repeats, lambda: m.sample(wi, u_lobe, u))}
        results["materials"][name] = row
        print("%-20s eval %.3f s  pdf %.3f s  sample %.3f s  (%d rows)" % (name, row["eval_s"], row["pdf_s"],
                                                                           row["sample_s"], n))

    kit = dict(samples=args.check_samples, progress=False, threads=args.threads)
    for name, bsdf in (("numpy Phong lobe (replayed)", PhongLobe(20)),
                       ("registry lambertian", sl.material({"type": "lambertian"}))):
        start = time.perf_counter()
        report = sl.check(bsdf, **kit)
        seconds = time.perf_counter() - start
        results["check"][name] = {"seconds": seconds, "passed": report.passed, "rows": len(report.rows)}
        print("check %-28s %.1f s  %s, %d rows (%d samples per chi-square test)" % (
            name, seconds, "PASS" if report.passed else "FAIL", len(report.rows), args.check_samples))

    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
