"""Threads: the motion is the same whatever their count, and their count follows the machine."""
import filecmp
import os
import subprocess
import time

from promise import expect, info_line, promise, shipped_scene


@promise(6, "the windy flag's motion is the same bit for bit on one thread and on two")
def motion_same_on_any_thread_count(run):
    scene = shipped_scene(run, "windy_flag", duration=1.0)
    threads = info_line(run.dinam("info", scene).output, "threads")
    expect("too small to share" not in threads, f"info says threads '{threads}'")
    for count in (1, 2):
        run.dinam("simulate", scene, "-o", f"on_{count}", "--threads", count, "--quiet")
    same = filecmp.cmp(run.path("on_1/cloth.pc2"), run.path("on_2/cloth.pc2"), shallow=False)
    expect(same, "the cloth's point cache differs between 1 and 2 threads")
    return "1 s of the windy flag: cloth.pc2 identical on 1 and 2 threads"


@promise(69, "with a busy process on every CPU, info says it saw them and starts on one thread, "
             "and the run that follows the load moves the flag as one thread does, bit for bit")
def own_choice_follows_the_load(run):
    cpus = os.cpu_count() or 1
    scene = shipped_scene(run, "windy_flag", duration=0.5)
    null = open(os.devnull, "w")
    busy = [subprocess.Popen(["yes"], stdout=null) for _ in range(cpus)]
    try:
        time.sleep(0.5)
        threads = info_line(run.dinam("info", scene).output, "threads")
        run.dinam("simulate", scene, "-o", "own", "--quiet")
        run.dinam("simulate", scene, "-o", "one", "--threads", 1, "--quiet")
    finally:
        for process in busy:
            process.kill()
            process.wait()
    if cpus == 1:
        expect(threads.startswith("1 ("), f"info says threads '{threads}'")
    else:
        expect(threads.startswith("1 (") and "runnable now" in threads and "so 1 of " in threads,
               f"with {cpus} busy processes on {cpus} CPUs info says threads '{threads}'")
    same = filecmp.cmp(run.path("own/cloth.pc2"), run.path("one/cloth.pc2"), shallow=False)
    expect(same, "the cloth's point cache differs between the own choice and one thread")
    return f"info: threads {threads.split(';')[-2].strip()}; cloth.pc2 as on one thread"
