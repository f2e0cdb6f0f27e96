"""dinam as a child process that can be watched and stopped: `dinam info --json` first, for the
run's estimate, then `dinam simulate`.

dinam writes a progress line to standard error each tenth of the frames when it is not a terminal
("simulate frame 36/120 (30%), ..."), which is read here on a thread so that Blender's interface
never waits for it. Stopping sends SIGTERM: dinam stops within a second and removes its unfinished
cache, and an older cache in the folder stays as it was.
"""
import json
import queue
import re
import shutil
import subprocess
import threading
import time

PROGRESS = re.compile(r"frame (\d+)/(\d+)")


def find_dinam(path):
    """The dinam program: `path` if it names one, else `dinam` on PATH; None when there is none."""
    if path and shutil.which(path):
        return shutil.which(path)
    return None


def estimate_text(estimate):
    """One line for the artist from what `dinam info --json` said: the run's estimated time, its
    memory, and the integrator dinam recommends."""
    seconds = estimate.get("estimated_run_s")
    if seconds is None:
        return "dinam gave no estimate"
    if seconds < 1:
        duration = "under a second"
    elif seconds < 90:
        duration = f"about {seconds:.0f} s"
    elif seconds < 5400:
        duration = f"about {seconds / 60:.0f} min"
    else:
        duration = f"about {seconds / 3600:.1f} h"
    text = f"estimate: {duration} to simulate"
    memory = estimate.get("memory_simulate_bytes")
    if memory:
        text += f", {memory / 1e6:.0f} MB"
    recommended = estimate.get("recommended_integrator")
    if recommended:
        text += f"; dinam recommends integrator {recommended}"
    return text


class DinamRun:
    """`dinam info SCENE --json` (with `estimate`), then `dinam simulate SCENE -o CACHE` (with
    `simulate`), one after the other on a thread; poll() from Blender's timer takes in what they
    said."""

    def __init__(self, program, scene, cache, estimate=True, simulate=True):
        self.lines = []  # everything dinam printed on stderr, but progress
        self.fraction = 0.0  # of the frames simulated
        self.estimate = None  # what `dinam info --json` said, once it has
        self._queue = queue.Queue()
        self._lock = threading.Lock()
        self._cancelled = False
        self._kill_at = None  # when a cancelled run that has not ended is killed
        self._code = None
        self._steps = []
        if estimate:
            self._steps.append([program, "info", scene, "--json"])
        if simulate:
            self._steps.append([program, "simulate", scene, "-o", cache, "--format", "pc2"])
        # The first is started here, so that a program that cannot run raises OSError at once.
        self._process = self._start(self._steps.pop(0))
        self._driver = threading.Thread(target=self._drive, daemon=True)
        self._driver.start()

    @staticmethod
    def _start(args):
        quiet_output = args[1] != "info"  # info's output is its JSON
        return subprocess.Popen(args, stdout=subprocess.DEVNULL if quiet_output else subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)

    def _drive(self):
        process = self._process
        while True:
            if process.args[1] == "info":
                out, err = process.communicate()
                if process.returncode == 0:
                    try:
                        self._queue.put(("estimate", json.loads(out)))
                    except ValueError:
                        pass
                else:  # the scene is refused: what info said is the run's error
                    for line in err.splitlines():
                        self._queue.put(line)
                # Its warnings, when it ran, are simulate's too, and come with it.
            else:
                for line in process.stderr:
                    self._queue.put(line.rstrip("\n"))
                process.wait()
            with self._lock:
                if process.returncode != 0 or self._cancelled or not self._steps:
                    self._code = process.returncode
                    return
                try:
                    process = self._process = self._start(self._steps.pop(0))
                except OSError as e:
                    self._queue.put(f"error: cannot run dinam: {e}")
                    self._code = 127
                    return

    def poll(self):
        """Takes in what dinam printed; returns its exit code, or None while it runs. A run
        cancelled with request_cancel that has not ended by its grace is killed here."""
        with self._lock:
            process = self._process
        if self._kill_at is not None and time.monotonic() >= self._kill_at and \
                process.poll() is None:
            process.kill()
        done = not self._driver.is_alive()
        while not self._queue.empty():
            item = self._queue.get()
            if isinstance(item, tuple):
                self.estimate = item[1]
                continue
            match = PROGRESS.search(item)
            if match:
                self.fraction = int(match.group(1)) / int(match.group(2))
            else:
                self.lines.append(item)
        return self._code if done else None

    def wait(self):
        self._driver.join()
        return self.poll()

    def request_cancel(self, grace=5.0):
        """Asks dinam to stop (SIGTERM) and returns at once: poll() reports the end, and kills it
        after `grace` seconds if it has not ended (dinam honours SIGTERM within a second)."""
        with self._lock:
            if self._cancelled:
                return
            self._cancelled = True
            if self._process.poll() is None:
                self._process.terminate()
            self._kill_at = time.monotonic() + grace

    def cancel(self, grace=5.0):
        """Stops dinam (SIGTERM) and waits for it; returns its exit code.

        dinam honours SIGTERM within a second in any of its loops; one that has not ended after
        `grace` seconds is killed, so Blender never waits longer than that.
        """
        self.request_cancel(grace)
        while True:
            code = self.poll()
            if code is not None:
                return code
            time.sleep(0.05)

    def message(self):
        """What dinam said, other than progress: its errors and warnings."""
        return "\n".join(self.lines)
