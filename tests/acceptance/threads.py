"""Threads: the motion is the same whatever their count."""
import filecmp

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
