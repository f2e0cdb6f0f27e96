#!/usr/bin/env python3
"""dinam's own thread count against fixed ones, with other work beside it (issue 69).

    python3 bench/threads_under_load.py build/dinam [--busy 0,1,2,4] [--repeats 2]
                                        [--only windy_flag|cloth140]

Two runs, each `dinam simulate` as a user types it: the shipped windy flag cut to 1 s, and a
140 x 140 cloth (59 080 bars, a wire-like material, pinned along one edge, 0.2 s). For each count
of busy processes beside it (`yes > /dev/null`, started a second before and stopped after), each
run is timed with no `--threads` (the own choice, which looks at the machine as it starts and
follows it as it runs: core/thread_governor.hpp), with `--threads 1` and with `--threads 2`, the
three in turn (in an order that turns each round), `repeats` times; each cell is the median of
its runs, in seconds, and the own choice against one thread the median of each round's ratio.

Prints one table, and the issue's two targets beside their figures: with two busy processes the
own choice within 1.15 x `--threads 1` on the windy flag; on an idle machine the cloth at least
1.6 x faster on 2 threads than on 1. Exits non-zero where a target measured here is missed. The
machine should have nothing else to do: the busy processes are the load.
"""
import argparse
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CLOTH_140 = """version: 1
name: cloth140
duration: 0.2
fps: 25
objects:
  - name: cloth
    mesh:
      grid: {width: 1.4, height: 1.4, columns: 140, rows: 140, diagonals: one}
      translation: [0, 0, 1.0]
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
    pinned: {box: {min: [-1, -1, 0], max: [0.001, 2, 2]}}
"""

MODES = {"own": [], "1": ["--threads", "1"], "2": ["--threads", "2"]}


def scenes(folder):
    """The two scene files, written into `folder`: the windy flag with its asset paths made
    absolute and its duration cut to 1 s, and the cloth."""
    flag = open(os.path.join(REPO, "scenes", "windy_flag.yaml")).read()
    flag = flag.replace("../assets/", os.path.join(REPO, "assets") + "/")
    flag = flag.replace("duration: 6.0", "duration: 1.0")
    assert "duration: 1.0" in flag, "scenes/windy_flag.yaml no longer says 'duration: 6.0'"
    paths = {}
    for name, text in (("windy_flag", flag), ("cloth140", CLOTH_140)):
        paths[name] = os.path.join(folder, name + ".yaml")
        with open(paths[name], "w") as out:
            out.write(text)
    return paths


def start_busy(count):
    null = open(os.devnull, "w")
    return [subprocess.Popen(["yes"], stdout=null) for _ in range(count)]


def stop(processes):
    for process in processes:
        process.send_signal(signal.SIGTERM)
    for process in processes:
        process.wait()


def timed_run(dinam, scene, arguments, folder):
    cache = os.path.join(folder, "cache")
    shutil.rmtree(cache, ignore_errors=True)
    env = {k: v for k, v in os.environ.items() if k != "DINAM_THREADS"}
    started = time.monotonic()
    finished = subprocess.run([dinam, "simulate", scene, "-o", cache, *arguments],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                              env=env)
    seconds = time.monotonic() - started
    if finished.returncode != 0:
        sys.exit(f"dinam simulate {scene} {' '.join(arguments)} failed: {finished.stderr}")
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dinam")
    parser.add_argument("--busy", default="0,1,2,4")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--only", choices=["windy_flag", "cloth140"])
    options = parser.parse_args()
    dinam = os.path.abspath(options.dinam)
    busy_counts = [int(b) for b in options.busy.split(",")]

    with tempfile.TemporaryDirectory(prefix="threads_under_load") as folder:
        paths = scenes(folder)
        names = [options.only] if options.only else list(paths)
        medians = {}
        for busy in busy_counts:
            load = start_busy(busy)
            try:
                time.sleep(1.0)
                for name in names:
                    times = {mode: [] for mode in MODES}
                    for repeat in range(options.repeats):
                        # The order turns each round, so that no mode always follows another.
                        order = list(MODES)[repeat % 3:] + list(MODES)[:repeat % 3]
                        for mode in order:
                            times[mode].append(timed_run(dinam, paths[name], MODES[mode], folder))
                    medians[name, busy] = {m: statistics.median(t) for m, t in times.items()}
                    # Own against one thread round by round: the load's effect drifts over minutes
                    # on a shared machine, and a round's two runs are seconds apart.
                    medians[name, busy]["own/1"] = statistics.median(
                        o / one for o, one in zip(times["own"], times["1"]))
                    print(f"  {name}, {busy} busy: " + ", ".join(
                        f"{m} {' '.join(f'{t:.2f}' for t in ts)}" for m, ts in times.items()),
                        flush=True)
            finally:
                stop(load)

    print(f"\n{os.cpu_count()} CPUs; seconds a run, the median of {options.repeats}\n")
    print("| run | busy processes | own choice | --threads 1 | --threads 2 "
          "| own / 1 thread, round by round | 1 thread / 2 threads |")
    print("|---|---|---|---|---|---|---|")
    for (name, busy), m in medians.items():
        print(f"| {name} | {busy} | {m['own']:.2f} | {m['1']:.2f} | {m['2']:.2f} "
              f"| {m['own/1']:.2f} | {m['1'] / m['2']:.2f} |")

    missed = []
    if ("windy_flag", 2) in medians:
        ratio = medians["windy_flag", 2]["own/1"]
        print(f"\nwindy flag, 2 busy: own choice {ratio:.2f} x --threads 1 (target at most 1.15)")
        if ratio > 1.15:
            missed.append("the own choice under load")
    if ("cloth140", 0) in medians:
        gain = medians["cloth140", 0]["1"] / medians["cloth140", 0]["2"]
        print(f"cloth 140 x 140, idle: 2 threads {gain:.2f} x faster than 1 (target at least 1.6)")
        if gain < 1.6:
            missed.append("the idle gain")
    if missed:
        sys.exit("missed: " + ", ".join(missed))


if __name__ == "__main__":
    main()
