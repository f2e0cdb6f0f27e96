#!/usr/bin/env python3
"""The real-mesh sweep: `dinam info --json` on a fixed list of assimp's test models, each dropped
as a 1 m rubber wireframe, as a new user would try them.

Checks, for every file of the list: no crash and no hang (a time limit per file); a file marked
`loads` exits 0 and its run-time estimate is under an hour; a file marked `refused` exits 2 with
a message naming it. Also that the FBX unit is read from the file. Prints a table of the step
counts and estimates.

Usage: real_mesh_sweep.py DINAM LIST [MODELS]"""
import json
import os
import subprocess
import sys
import tempfile

MODELS = "/usr/share/assimp/models"
HOUR = 3600.0
# The sweep's scene: the rubbery wire, fitted to 1 m and dropped from 0.5 m for 3 s (it
# lands in 0.3 s and comes to rest on the ground).
SCENE = """version: 1
duration: 3
fps: 20
objects:
  - mesh: {{file: "{file}", {placement}}}
    material: {{density: 1100, youngs_modulus: 5.0e7, radius: 0.004}}
    style: wire
"""


def info(dinam, folder, path, placement="fit: {size: 1}, translation: [0, 0, 0.5]"):
    scene = os.path.join(folder, "scene.yaml")
    with open(scene, "w", encoding="utf-8") as out:
        out.write(SCENE.format(file=path, placement=placement))
    try:
        run = subprocess.run([dinam, "info", "--json", scene], capture_output=True, text=True,
                             errors="replace", timeout=120)
    except subprocess.TimeoutExpired:
        return None, "no answer within 120 s (a hang)"
    return run, run.stderr.strip()


def main():
    dinam, listing = sys.argv[1], sys.argv[2]
    models = sys.argv[3] if len(sys.argv) > 3 else MODELS
    if not os.path.isdir(models):
        print(f"{models} is missing: install Debian's assimp-testmodels (scripts/install-deps.sh)")
        return 1
    entries = []
    with open(listing, encoding="utf-8") as lines:
        for line in lines:
            if line.strip() and not line.startswith("#"):
                expected, name = line.split(None, 1)
                entries.append((expected, name.strip()))
    failures = []
    rows = []
    with tempfile.TemporaryDirectory(prefix="dinam-sweep-") as folder:
        for expected, name in entries:
            path = os.path.join(models, name)
            run, messages = info(dinam, folder, path)
            if run is None:
                failures.append(f"{name}: {messages}")
                continue
            if run.returncode < 0 or run.returncode not in (0, 2):
                failures.append(f"{name}: exit {run.returncode}: {messages[-400:]}")
            elif expected == "loads" and run.returncode != 0:
                failures.append(f"{name}: refused, expected to load: {messages[-400:]}")
            elif expected == "refused" and run.returncode != 2:
                failures.append(f"{name}: loaded, expected to be refused")
            elif expected == "refused" and name.split("/")[-1] not in messages:
                failures.append(f"{name}: refused without naming the file: {messages[-400:]}")
            elif expected == "loads":
                summary = json.loads(run.stdout)
                rows.append((name, summary))
                if summary["estimated_run_s"] >= HOUR:
                    failures.append(f"{name}: estimated {summary['estimated_run_s']:.0f} s, over "
                                    f"an hour ({summary['steps']} steps)")
        # FBX states its unit: box.fbx is in metres (UnitScaleFactor 100), the cubes in cm (1).
        for name, largest in (("FBX/box.fbx", 0.529306), ("FBX/cubes_with_names.fbx", 0.327711)):
            run, messages = info(dinam, folder, os.path.join(models, name), "translation: [0, 0, 1]")
            if run is None or run.returncode != 0:
                failures.append(f"{name} without fit: {messages[-400:]}")
                continue
            lo, hi = json.loads(run.stdout)["bounding_box_m"]
            side = max(h - l for l, h in zip(lo, hi))
            if abs(side - largest) > 1e-3 * largest:
                failures.append(f"{name}: largest side {side:.6g} m, the file's unit gives "
                                f"{largest} m")

    rows.sort(key=lambda row: -row[1]["estimated_run_s"])
    print(f"{'file':52} {'bars':>7} {'steps':>10} {'added':>7} {'estimate':>9}")
    for name, s in rows:
        print(f"{name[:52]:52} {s['bars']:7d} {s['steps']:10d} "
              f"{100 * s['added_mass_fraction']:6.2f}% {s['estimated_run_s']:8.1f}s")
    loads = sum(1 for e, _ in entries if e == "loads")
    print(f"{len(entries)} files: {loads} to load, {len(entries) - loads} to refuse; "
          f"{len(failures)} failures")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
