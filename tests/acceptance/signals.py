"""Stops: a signal is honoured within a second, and what was done is kept, cleanly."""
import signal
import subprocess
import time

from promise import SOURCE, expect, promise


@promise(15, "SIGINT stops a render within a second: exit 130, complete frames kept, no "
             "temporary file, no movie, and a message that says so")
def interrupt_honoured_within_a_second(run):
    process = run.start("render", SOURCE / "scenes/flag.yaml", "-o", "out",
                        stdout=subprocess.PIPE)
    deadline = time.monotonic() + 120
    while not run.path("out/frame_0010.png").exists():
        expect(process.poll() is None and time.monotonic() < deadline,
               "the render ended, or wrote no 10th frame in 2 minutes")
        time.sleep(0.02)
    process.send_signal(signal.SIGINT)
    sent = time.monotonic()
    try:
        output, _ = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
        raise
    took = time.monotonic() - sent
    left = [p.name for p in run.path("out").iterdir() if ".tmp" in p.name or ".part" in p.name]
    frames = len(list(run.path("out").glob("frame_*.png")))
    last = output.strip().splitlines()[-1] if output.strip() else ""
    expect(process.returncode == 130, f"exit {process.returncode}, 130 expected: {last}")
    expect(took < 1.0, f"it took {took:.2f} s to stop")
    expect(not left and not run.path("out/flag.mp4").exists(),
           f"left behind: {left}, movie {run.path('out/flag.mp4').exists()}")
    expect(f"{frames} of the 120 frames" in last and "kept" in last and "no movie" in last,
           f"{frames} frames kept, the last line says '{last}'")
    return f"stopped in {took:.2f} s, exit 130, {frames} frames kept: '{last[:80]}'"
