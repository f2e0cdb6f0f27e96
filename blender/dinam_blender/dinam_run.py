"""`dinam simulate` as a child process that can be watched and stopped.

dinam writes a progress line to standard error each tenth of the frames when it is not a terminal
("simulate frame 36/120 (30%), ..."), which is read here on a thread so that Blender's interface
never waits for it. Stopping sends SIGTERM: dinam stops within a second and removes its unfinished
cache, and an older cache in the folder stays as it was.
"""
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


class DinamRun:
    def __init__(self, program, scene, cache):
        self.lines = []  # everything dinam printed on stderr
        self.fraction = 0.0  # of the frames simulated
        self._queue = queue.Queue()
        self._kill_at = None  # when a cancelled run that has not ended is killed
        self._process = subprocess.Popen(
            [program, "simulate", scene, "-o", cache, "--format", "pc2"],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self._process.stderr:
            self._queue.put(line.rstrip("\n"))

    def poll(self):
        """Takes in what dinam printed; returns its exit code, or None while it runs. A run
        cancelled with request_cancel that has not ended by its grace is killed here."""
        code = self._process.poll()
        if code is None and self._kill_at is not None and time.monotonic() >= self._kill_at:
            self._process.kill()
            code = self._process.wait()
        if code is not None:
            self._reader.join()
        while not self._queue.empty():
            line = self._queue.get()
            match = PROGRESS.search(line)
            if match:
                self.fraction = int(match.group(1)) / int(match.group(2))
            else:
                self.lines.append(line)
        return code

    def wait(self):
        self._process.wait()
        return self.poll()

    def request_cancel(self, grace=5.0):
        """Asks dinam to stop (SIGTERM) and returns at once: poll() reports the end, and kills it
        after `grace` seconds if it has not ended (dinam honours SIGTERM within a second)."""
        if self._process.poll() is None and self._kill_at is None:
            self._process.terminate()
            self._kill_at = time.monotonic() + grace

    def cancel(self, grace=5.0):
        """Stops dinam (SIGTERM) and waits for it; returns its exit code.

        dinam honours SIGTERM within a second in any of its loops; one that has not ended after
        `grace` seconds is killed, so Blender never waits longer than that.
        """
        if self._process.poll() is None:
            self._process.terminate()
            try:
                self._process.wait(timeout=grace)
            except subprocess.TimeoutExpired:
                self._process.kill()
        return self.wait()

    def message(self):
        """What dinam said, other than progress: its errors and warnings."""
        return "\n".join(self.lines)
