#!/usr/bin/env python3
"""Render-time comparison of `scatterlab render` with Blender Cycles on the peers' scene.

    bench/cycles_compare.py [--res 256 512] [--spp 64] [--threads 2] [--repeats 3]
                            [--materials diffuse metal glass roughglass sss_burley sss_rw]
                            [--envs furnace synthetic] [--stats] [--json FILE]

For every (environment, resolution, material) it runs scatterlab and Cycles alternately
(A B A B ...), `--repeats` times each, in one session (these machines drift), and reports the
medians: scatterlab's whole-process wall time (start-up, map loading, sampling tables,
path tracing, writing EXR and PNG) and its path-tracing time alone, Cycles' render_s (the
render call: scene sync, BVH, path tracing; Blender's own start-up is not counted), their
ratio, and path vertices per second. The target is ratio <= 0.5 for diffuse,
rough metal, glass and rough glass at 256 and 512 pixels, 64 spp, 2 threads. sss_burley and
sss_rw (not in the default list) time subsurface spheres against Cycles' Principled
subsurface methods: scatterlab's diffusion mode and its random walk.

The materials are set as bench/cycles/cycles_sphere.py sets them: colour 1, roughness 0.3
(GGX alpha 0.09), IOR 1.5; Cycles' Principled metal with base colour 1 has F = 1. "synthetic"
is bench/cycles/make_envmap.py's map (written once into the output directory with Blender);
any other value of --envs is a path to an equirectangular EXR (e.g. data/envmaps/city.exr).

Without Blender on PATH (Debian: apt-get install blender python3-numpy) only scatterlab is
timed. --stats also compares the two images' sphere means with the peers' pixel mask.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

MATERIALS = {
    "diffuse": {"type": "lambertian", "albedo": 1},
    "metal": {"type": "conductor", "distribution": "ggx", "alpha": 0.09, "eta": [1, 1, 1], "k": [1e8, 1e8, 1e8]},
    "glass": {"type": "dielectric", "eta": 1.5},
    "roughglass": {"type": "rough-dielectric", "distribution": "ggx", "alpha": 0.09, "eta": 1.5},
    # cycles_sphere.py's Principled subsurface: colour 1, radius 0.1 for every channel, IOR 1.4.
    # Here Burley's profile with that diffuse colour and mean free path, and the random walk of
    # the medium it implies (an albedo-1 medium: both render 1 in the furnace).
    "sss_burley": {"type": "subsurface", "profile": "burley", "reflectance": 1, "mfp": 0.1, "eta": 1.4},
    "sss_rw": {"type": "subsurface", "profile": "burley", "reflectance": 1, "mfp": 0.1, "eta": 1.4},
}
SUBSURFACE_MODE = {"sss_burley": "diffusion", "sss_rw": "walk"}
BSDF_MATERIALS = ["diffuse", "metal", "glass", "roughglass"]


def blender_env():
    # Blender's embedded Python takes its prefix from the first python3 on PATH; a pyenv
    # bin/ there hides Debian's python3 packages from it (peers/cycles_sphere.sh does the same).
    env = dict(os.environ)
    env["PATH"] = ":".join(p for p in env.get("PATH", "").split(":") if "pyenv" not in p)
    return env


def find_blender():
    for directory in blender_env()["PATH"].split(":"):
        candidate = Path(directory) / "blender"
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


def run_blender(blender, script, args, log):
    cmd = [blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "1", "-P", str(script), "--"] + args
    with open(log, "w") as out:
        done = subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT, env=blender_env())
    text = Path(log).read_text()
    if done.returncode != 0:
        sys.exit(f"cycles_compare: Blender failed ({' '.join(cmd)}); see {log}")
    return text


def run_cycles(blender, material, env, res, spp, threads, prefix):
    text = run_blender(blender, HERE / "cycles" / "cycles_sphere.py",
                       ["--material", material, "--env", env, "--res", str(res), "--spp", str(spp),
                        "--threads", str(threads), "--out", prefix], prefix + ".log")
    line = [l for l in text.splitlines() if l.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT "):])


def run_scatterlab(exe, material, env, res, spp, threads, prefix):
    cmd = [exe, "render", json.dumps(MATERIALS[material]), "--env", "white" if env == "furnace" else env,
           "--res", f"{res}x{res}", "--spp", str(spp), "--threads", str(threads), "--out", prefix, "--json"]
    if material in SUBSURFACE_MODE:
        cmd += ["--subsurface", SUBSURFACE_MODE[material]]
    start = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"cycles_compare: scatterlab failed: {done.stderr.strip()}")
    run = json.loads(done.stdout)["renders"][0]
    return {"wall_s": wall, "render_s": run["seconds"], "vertices_per_s": run["vertices_per_second"],
            "sphere_mean": run["sphere"]["mean"], "background_mean": run["background"]["mean"]}


def exr_sphere_mean(blender, exr, log):
    text = run_blender(blender, HERE / "cycles" / "exr_stats.py", [exr], log)
    line = [l for l in text.splitlines() if l.startswith("STATS ")][-1]
    return json.loads(line[len("STATS "):])["sphere"]["mean"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--res", type=int, nargs="+", default=[256, 512])
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--materials", nargs="+", default=BSDF_MATERIALS, choices=list(MATERIALS))
    ap.add_argument("--envs", nargs="+", default=["furnace", "synthetic"])
    ap.add_argument("--scatterlab", default=str(ROOT / "build" / "release" / "app" / "scatterlab"))
    ap.add_argument("--out-dir", default=None, help="where images and logs go (default: a temporary directory)")
    ap.add_argument("--stats", action="store_true", help="also compare the sphere means of the two images")
    ap.add_argument("--json", help="write every measurement to this file")
    a = ap.parse_args()

    exe = a.scatterlab
    if not (Path(exe).is_file() and os.access(exe, os.X_OK)):
        sys.exit(f"cycles_compare: {exe} is not an executable; build it (cmake --build --preset release)")
    out = Path(a.out_dir or tempfile.mkdtemp(prefix="cycles-compare-"))
    out.mkdir(parents=True, exist_ok=True)
    blender = find_blender()
    if not blender:
        print("cycles_compare: Blender not found on PATH: timing scatterlab alone "
              "(Debian: apt-get install blender python3-numpy)", file=sys.stderr)

    envs = []
    for env in a.envs:
        if env == "synthetic":
            if not blender:
                print("cycles_compare: the synthetic map needs Blender to be written; skipped", file=sys.stderr)
                continue
            path = out / "synthetic.exr"
            if not path.exists():
                run_blender(blender, HERE / "cycles" / "make_envmap.py", [str(path)], str(out / "make_envmap.log"))
            envs.append(("synthetic", str(path)))
        else:
            envs.append((env if env == "furnace" else Path(env).stem, env))

    rows = []
    for env_name, env in envs:
        for res in a.res:
            for material in a.materials:
                ours, theirs = [], []
                for k in range(a.repeats):  # interleaved: A B A B ...
                    prefix = str(out / f"{env_name}-{material}-{res}")
                    ours.append(run_scatterlab(exe, material, env, res, a.spp, a.threads, prefix + "-scatterlab"))
                    if blender:
                        theirs.append(run_cycles(blender, material, env, res, a.spp, a.threads, prefix + "-cycles"))
                row = {"env": env_name, "res": res, "material": material, "spp": a.spp, "threads": a.threads,
                       "scatterlab_wall_s": statistics.median(r["wall_s"] for r in ours),
                       "scatterlab_render_s": statistics.median(r["render_s"] for r in ours),
                       "vertices_per_s": statistics.median(r["vertices_per_s"] for r in ours),
                       "scatterlab_sphere_mean": ours[0]["sphere_mean"], "runs": {"scatterlab": ours, "cycles": theirs}}
                if theirs:
                    row["cycles_render_s"] = statistics.median(r["render_s"] for r in theirs)
                    row["ratio"] = row["scatterlab_wall_s"] / row["cycles_render_s"]
                    if a.stats:
                        row["cycles_sphere_mean"] = exr_sphere_mean(blender, prefix + "-cycles.exr", prefix + "-stats.log")
                rows.append(row)
                print(json.dumps({k: v for k, v in row.items() if k != "runs"}), file=sys.stderr, flush=True)

    print(f"| env | res | material | scatterlab wall s | scatterlab path tracing s | Cycles render_s | ratio | "
          f"M vertices/s |{' sphere mean (ours / Cycles) |' if a.stats else ''}")
    print(f"|---|---|---|---|---|---|---|---|{'---|' if a.stats else ''}")
    for r in rows:
        cycles = f"{r['cycles_render_s']:.3f}" if "cycles_render_s" in r else "-"
        ratio = f"{r['ratio']:.2f}" if "ratio" in r else "-"
        stats = (f" {r['scatterlab_sphere_mean']:.4f} / {r['cycles_sphere_mean']:.4f} |"
                 if a.stats and "cycles_sphere_mean" in r else (" - |" if a.stats else ""))
        print(f"| {r['env']} | {r['res']} | {r['material']} | {r['scatterlab_wall_s']:.3f} | "
              f"{r['scatterlab_render_s']:.3f} | {cycles} | {ratio} | {r['vertices_per_s'] / 1e6:.2f} |{stats}")
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
