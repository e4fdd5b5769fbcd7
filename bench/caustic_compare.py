#!/usr/bin/env python3
"""Time to equal noise on the caustic scene: scatterlab's path tracer and BDPT, and Cycles' path
tracer (Cycles has no BDPT).

    bench/caustic_compare.py [--res 128 96] [--seeds 8] [--threads 2]
                             [--spp path=256 bdpt=32 cycles=256] [--json FILE]

Each estimator renders the caustic scene (`scatterlab render '{"type":"dielectric"}' --scene
caustic`; bench/cycles/cycles_caustic.py builds the same scene for Cycles) once per seed. In
the caustic region (ground pixels within 0.35 of where the light's line through the sphere's
centre meets the ground; only light through the glass reaches it) each pixel's variance is the
sample variance of its luminance over the seeds, the same way for all three. The time an
estimator needs to bring a typical pixel there to 1% relative standard error is
    render seconds per image x (mean over pixels of the variance) / (region mean)^2 / 1e-4,
since variance falls as 1 / samples while time grows with them. scatterlab's seconds are its
rendering alone (`--json` "seconds"), Cycles' the render call (scene sync and BVH included).
Needs Blender (Debian: apt-get install blender) to read the EXRs and to run Cycles.
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from cycles_compare import find_blender, run_blender  # noqa: E402

ROOT = HERE.parent
SCRIPT = HERE / "cycles" / "cycles_caustic.py"


def parse_spp(items):
    spp = {"path": 256, "bdpt": 32, "cycles": 256}
    for item in items:
        name, _, value = item.partition("=")
        if name not in spp or not value.isdigit():
            sys.exit(f"caustic_compare: --spp {item}: allowed: path=N, bdpt=N, cycles=N")
        spp[name] = int(value)
    return spp


def stats(blender, res, files, log):
    text = run_blender(blender, SCRIPT, ["stats", "--res", str(res[0]), str(res[1]), "--files"] + files, log)
    line = [l for l in text.splitlines() if l.startswith("STATS ")][-1]
    return json.loads(line[len("STATS "):])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--res", type=int, nargs=2, default=[128, 96])
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spp", nargs="*", default=[])
    ap.add_argument("--scatterlab", default=str(ROOT / "build" / "release" / "app" / "scatterlab"))
    ap.add_argument("--json")
    a = ap.parse_args()
    spp = parse_spp(a.spp)
    blender = find_blender()
    if blender is None:
        sys.exit("caustic_compare: needs Blender on PATH (Debian: apt-get install blender)")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for integrator in ("path", "bdpt"):
            files, seconds = [], []
            for seed in range(a.seeds):
                prefix = f"{tmp}/{integrator}_{seed}"
                cmd = [a.scatterlab, "render", '{"type":"dielectric"}', "--scene", "caustic", "--integrator",
                       integrator, "--res", f"{a.res[0]}x{a.res[1]}", "--spp", str(spp[integrator]),
                       "--threads", str(a.threads), "--seed", str(seed + 1), "--out", prefix, "--json"]
                done = subprocess.run(cmd, capture_output=True, text=True)
                if done.returncode != 0:
                    sys.exit(f"caustic_compare: scatterlab failed: {done.stderr.strip()}")
                seconds.append(json.loads(done.stdout)["renders"][0]["seconds"])
                files.append(prefix + ".exr")
            s = stats(blender, a.res, files, f"{tmp}/{integrator}_stats.log")
            rows.append({"estimator": "scatterlab " + integrator, "spp": spp[integrator],
                         "seconds": sum(seconds) / len(seconds), **s})
        text = run_blender(blender, SCRIPT, ["render", "--res", str(a.res[0]), str(a.res[1]), "--spp",
                                             str(spp["cycles"]), "--seeds", str(a.seeds), "--threads",
                                             str(a.threads), "--out", tmp], f"{tmp}/cycles.log")
        line = [l for l in text.splitlines() if l.startswith("RESULT ")][-1]
        result = json.loads(line[len("RESULT "):])
        s = stats(blender, a.res, [f"{tmp}/cycles_{k}.exr" for k in range(a.seeds)], f"{tmp}/cycles_stats.log")
        rows.append({"estimator": result["peer"] + " path", "spp": spp["cycles"],
                     "seconds": sum(result["seconds"]) / len(result["seconds"]), **s})
    for row in rows:
        row["seconds_to_1_percent"] = row["seconds"] * row["relative_variance"] / 1e-4
    print(f"caustic region: {rows[0]['pixels']} pixels of {a.res[0]} x {a.res[1]}, {a.seeds} seeds, "
          f"{a.threads} threads")
    print(f"{'estimator':28} {'spp':>5} {'s/image':>8} {'rel. var':>10} {'s to 1%':>9}")
    for row in rows:
        print(f"{row['estimator']:28} {row['spp']:5d} {row['seconds']:8.3f} {row['relative_variance']:10.4g} "
              f"{row['seconds_to_1_percent']:9.1f}")
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=1) + "\n")


if __name__ == "__main__":
    main()
