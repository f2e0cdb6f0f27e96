#!/usr/bin/env python3
"""`dinam info`'s estimates against the runs themselves: each run's time and its peak memory.

    python3 bench/estimate_check.py build/dinam [--budget S] [--only NAME] [--no-other]

For each scene of a fixed set -- the shipped scenes, a swinging steel cable, assimp's Wuson and
the real-mesh sweep's slowest models (bench/notes/implicit-integrator.md) -- it asks `dinam info
--json` which integrator it recommends and what the run would take, runs `dinam simulate` with
that integrator and times it, and prints the measured time over the estimate. A run whose estimate
passes the budget (default 30 s) is shortened to a duration whose estimate fits, and estimated
again as shortened. With the other integrator too (unless --no-other: central differences beside any other
recommendation, xpbd beside central differences), each run stopped at four times its estimate or
120 s. Each run's peak resident memory is read from the kernel (wait4's ru_maxrss) and set
beside `info`'s "memory, simulate" estimate (src/estimate/memory_estimate.hpp). Where the machine
was busy when `info` timed a step, its headline ("measured now") is shown too.

Exits non-zero where a recommended run is off its time estimate by more than a factor of two, or
where any run holds over 15 % more memory than its estimate (the bound the memory test
keeps, tests/estimate/memory_estimate_test.cpp): those are the promises `info`
makes (a run under its memory estimate is safe, the estimate being what refuses a run too big for
the machine).

The machine should be otherwise idle: the runs are timed by the wall clock.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ASSIMP = "/usr/share/assimp/models"

# The swinging steel cable of tests/app/info_test.cpp: BDF2 keeps its swing.
STEEL_CABLE = """version: 1
duration: 3
ground: {contact: false}
objects:
  - name: cable
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 100}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.001}
    pinned: {indices: [0]}
"""

# The real-mesh sweep's scene (a rubbery wire fitted to 1 m and dropped from 0.5 m for 3 s), as
# tests/real_meshes/real_mesh_sweep.py defines it.
sys.path.insert(0, os.path.join(REPO, "tests", "real_meshes"))
from real_mesh_sweep import SCENE as SWEEP  # noqa: E402
SWEEP_PLACEMENT = "fit: {size: 1}, translation: [0, 0, 0.5]"
SWEEP_MODELS = [
    "OFF/Wuson.off",
    "Collada/COLLADA.dae",
    "OpenGEX/collada.ogex",
    "DXF/issue_2229.dxf",
    "ASE/MotionCaptureROM.ase",
    "X/fromtruespace_bin32.x",
    "Q3D/E-AT-AT.q3o",
    "BLEND/HUMAN.blend",
    "NFF/NFF/spheres.nff",
    "NFF/NFF/WithCamera.nff",
    "AC/SphereWithLight.ac",
]


def scenes(folder):
    """(name, path) of every scene of the set that this machine has."""
    shipped = os.path.join(REPO, "scenes")
    for name in sorted(os.listdir(shipped)):
        if name.endswith(".yaml"):
            yield name[:-5], os.path.join(shipped, name)
    cable = os.path.join(folder, "scenes", "steel_cable.yaml")
    with open(cable, "w") as f:
        f.write(STEEL_CABLE)
    yield "steel_cable", cable
    for model in SWEEP_MODELS:
        path = os.path.join(ASSIMP, model)
        if os.path.exists(path):
            scene = os.path.join(folder, "scenes", os.path.basename(model) + ".yaml")
            with open(scene, "w") as f:
                f.write(SWEEP.format(file=path, placement=SWEEP_PLACEMENT))
            yield os.path.basename(model), scene


def top_level(text, key):
    match = re.search(r"^%s:\s*(.*?)\s*(#.*)?$" % key, text, re.M)
    return match.group(1) if match else None


def with_keys(text, **keys):
    """The scene's text with top-level single-line keys set (None: removed)."""
    for key, value in keys.items():
        text = re.sub(r"^%s:.*\n" % key, "", text, flags=re.M)
        if value is not None:
            text = re.sub(r"^(version:.*\n)", r"\g<1>%s: %s\n" % (key, value), text, count=1,
                          flags=re.M)
    return text


def info(dinam, scene):
    out = subprocess.run([dinam, "info", "--json", scene], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(out.stdout + out.stderr)
    return json.loads(out.stdout)


def timed_run(dinam, scene, output, timeout):
    """(seconds, peak bytes): the seconds the run took as `dinam simulate` reports it (its settle
    and steps, what `info` estimates; not the model's build or the process's start), None past
    `timeout`; and its peak resident memory, as the kernel counted it."""
    log = tempfile.TemporaryFile(mode="w+")
    child = subprocess.Popen([dinam, "simulate", scene, "-o", output, "--force"], stdout=log,
                             stderr=subprocess.STDOUT, text=True)
    start = time.monotonic()
    while True:
        pid, status, usage = os.wait4(child.pid, os.WNOHANG)
        if pid == child.pid:
            break
        if timeout is not None and time.monotonic() - start > timeout:
            child.kill()
            _, status, usage = os.wait4(child.pid, 0)
            child.returncode = -1
            return None, usage.ru_maxrss * 1024
        time.sleep(0.02)
    child.returncode = os.waitstatus_to_exitcode(status)
    log.seek(0)
    out = log.read()
    if child.returncode != 0:
        raise RuntimeError(out)
    match = re.search(r"motion cache of .*; ([0-9.]+) s\)", out)
    if not match:
        raise RuntimeError("no run time in: " + out[-300:])
    return float(match.group(1)), usage.ru_maxrss * 1024


def variant(folder, name, source, integrator, duration, own_integrator):
    """The scene with `integrator` (and the scene's own `timestep` only for its own integrator),
    `duration` seconds long, written where its relative paths still hold (../assets)."""
    with open(source) as f:
        text = f.read()
    keys = {"integrator": integrator, "duration": repr(duration)}
    if integrator != own_integrator:
        keys["timestep"] = None
    path = os.path.join(folder, "scenes", "%s.%s.yaml" % (name, integrator))
    with open(path, "w") as f:
        f.write(with_keys(text, **keys))
    return path


def measure(dinam, folder, name, source, integrator, own, budget, timeout_for):
    with open(source) as f:
        duration = float(top_level(f.read(), "duration") or 1.0)
    scene = variant(folder, name, source, integrator, duration, own)
    estimate = info(dinam, scene)
    seconds = estimate["estimated_run_s"]
    fps = estimate["fps"]
    if seconds > budget:  # shortened, in whole frames, and estimated again
        frames = max(2, math.floor(duration * fps * budget / seconds))
        duration = frames / fps
        scene = variant(folder, name, source, integrator, duration, own)
        estimate = info(dinam, scene)
        seconds = estimate["estimated_run_s"]
    timeout = timeout_for(seconds)
    measured, peak = timed_run(dinam, scene, os.path.join(folder, "out", name + "." + integrator),
                               timeout)
    return duration, estimate, measured, peak, timeout


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dinam")
    parser.add_argument("--budget", type=float, default=30.0)
    parser.add_argument("--only")
    parser.add_argument("--no-other", action="store_true")
    args = parser.parse_args()
    dinam = os.path.abspath(args.dinam)
    folder = tempfile.mkdtemp(prefix="dinam-estimates-")
    os.makedirs(os.path.join(folder, "scenes"))
    os.makedirs(os.path.join(folder, "out"))
    os.symlink(os.path.join(REPO, "assets"), os.path.join(folder, "assets"))
    print("%-26s %-20s %-9s %8s %10s %8s %10s %6s %8s %8s %6s" %
          ("scene", "recommended", "integr.", "length s", "estimate s", "now s", "measured s",
           "ratio", "est. MB", "peak MB", "ratio"))
    off = []
    over_memory = []
    try:
        for name, source in scenes(folder):
            if args.only and args.only != name:
                continue
            whole = info(dinam, source)
            recommended = whole["recommended_integrator"]
            with open(source) as f:
                own = top_level(f.read(), "integrator") or "central_difference"
            # Central differences beside any other recommendation (is it faster than they?), and
            # the bars as constraints beside central differences (would it be?).
            other = "xpbd" if recommended == "central_difference" else "central_difference"
            others = [] if args.no_other else [other]
            for integrator in [recommended] + others:
                chosen = integrator == recommended
                duration, estimate, measured, peak, timeout = measure(
                    dinam, folder, name, source, integrator, own, args.budget,
                    (lambda s: None) if chosen else (lambda s: min(max(4.0 * s, 10.0), 120.0)))
                seconds = estimate["estimated_run_s"]
                ratio = measured / seconds if measured is not None and seconds > 0 else None
                shown = "%.2f" % measured if measured is not None else "> %.0f" % timeout
                # info's headline where the machine was busy: the step it timed, times the steps.
                now = estimate.get("measured_run_s")
                memory = estimate["memory_simulate_bytes"]
                memory_ratio = peak / memory if memory > 0 else None
                # A run cut at its timeout had not reached its peak: its memory is not compared.
                memory_over = measured is not None and memory_ratio is not None and \
                    memory_ratio > 1.15
                notes = []
                if chosen and (ratio is None or not 0.5 <= ratio <= 2.0):
                    notes.append("time off by more than 2x")
                    off.append(name)
                if memory_over:
                    notes.append("memory over its estimate")
                    over_memory.append("%s (%s)" % (name, integrator))
                print("%-26s %-20s %-9s %8.2f %10.2f %8s %10s %6s %8.1f %8.1f %6.2f%s" %
                      (name, recommended if chosen else "", integrator.replace(
                          "central_difference", "central"), duration, seconds,
                       "%.2f" % now if now else "", shown,
                       "%.2f" % ratio if ratio is not None else "", memory / 1e6, peak / 1e6,
                       memory_ratio if memory_ratio is not None else 0.0,
                       "  <- " + ", ".join(notes) if notes else ""), flush=True)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    if off:
        print("recommended runs off their time estimate by more than 2x: " + ", ".join(off))
    if over_memory:
        print("runs over their memory estimate by more than 15 %: " + ", ".join(over_memory))
    if off or over_memory:
        return 1
    print("every recommended run within 2x of its time estimate; no run over its memory estimate")
    return 0


if __name__ == "__main__":
    sys.exit(main())
