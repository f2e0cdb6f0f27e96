"""What every acceptance check shares: the register of promises, and running dinam as a user
does (the built program, a scene file in a folder of its own, what it prints and writes).

A promise is a function of one argument, a `Run`, registered with `@promise(issue, text)`: it
runs the program, reads what a user would read (the printed table, the files, the movie) and
returns the figure it checked, as one line; it raises `Broken` with what it saw when the promise
no longer holds."""
import os
import struct
import subprocess
import threading
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
PROMISES = {}  # name -> (issue, text, function), in the order the files define them


class Broken(Exception):
    """The promise no longer holds; the message says what was seen instead."""


def promise(issue, text):
    def register(function):
        module = function.__module__.rsplit(".", 1)[-1]
        PROMISES[f"{module}.{function.__name__}"] = (issue, text, function)
        return function
    return register


def expect(condition, message):
    if not condition:
        raise Broken(message)


def near(value, reference, relative):
    return abs(value - reference) <= relative * abs(reference)


class Finished:
    def __init__(self, code, output, seconds, max_rss_kb):
        self.code, self.output, self.seconds, self.max_rss_kb = code, output, seconds, max_rss_kb

    def tail(self, lines=3):
        return " | ".join(self.output.strip().splitlines()[-lines:])


class Run:
    """One promise's run: a fresh folder, and dinam run in it as a user would."""

    def __init__(self, program, folder):
        self.program, self.folder = str(program), Path(folder)

    def path(self, name):
        return self.folder / name

    def scene(self, name, text):
        path = self.folder / name
        path.write_text(text)
        return path

    def start(self, *arguments, stdout=subprocess.PIPE):
        return subprocess.Popen([self.program, *map(str, arguments)], cwd=self.folder,
                                stdout=stdout, stderr=subprocess.STDOUT, text=True)

    def dinam(self, *arguments, timeout=300, ok=True):
        """Runs dinam with `arguments` to its end: its exit status, what it printed (both
        streams), its wall time and its peak resident memory. With `ok`, a non-zero exit breaks
        the promise."""
        started = time.monotonic()
        process = self.start(*arguments, stdout=subprocess.PIPE)
        timer = threading.Timer(timeout, process.kill)
        timer.start()
        output = process.stdout.read()
        # Reaped here rather than by Popen, for this child's own peak memory.
        _, status, usage = os.wait4(process.pid, 0)
        timer.cancel()
        process.returncode = os.waitstatus_to_exitcode(status)
        process.stdout.close()
        seconds = time.monotonic() - started
        expect(seconds < timeout, f"dinam {' '.join(map(str, arguments))} ran past {timeout} s")
        finished = Finished(process.returncode, output, seconds, usage.ru_maxrss)
        if ok:
            expect(finished.code == 0, f"dinam {' '.join(map(str, arguments))} exited "
                                       f"{finished.code}: {finished.tail()}")
        return finished


def shipped_scene(run, name, duration=None):
    """A copy of scenes/NAME.yaml in the run's folder, its paths to assets/ kept, and its
    duration cut to `duration` seconds where given (a shorter run of the same motion)."""
    text = (SOURCE / "scenes" / f"{name}.yaml").read_text()
    text = text.replace("../assets/", f"{SOURCE / 'assets'}/")
    if duration is not None:
        lines = text.splitlines()
        at = next(k for k, l in enumerate(lines) if l.startswith("duration:"))
        lines[at] = f"duration: {duration}"
        text = "\n".join(lines) + "\n"
    return run.scene(f"{name}.yaml", text)


def read_pc2(path):
    """A PC2 point cache: every sample's points as (x, y, z) tuples."""
    data = Path(path).read_bytes()
    signature, version, points, _, _, samples = struct.unpack_from("<12siiffi", data)
    expect(signature == b"POINTCACHE2\0" and version == 1, f"{path} is not a PC2 file")
    frame = struct.Struct(f"<{3 * points}f")
    return [[frame.unpack_from(data, 32 + k * frame.size)[3 * i:3 * i + 3] for i in range(points)]
            for k in range(samples)]


def png_size(path):
    """The width and height a PNG's header gives."""
    data = Path(path).read_bytes()[:24]
    expect(data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    return struct.unpack(">II", data[16:24])


def modes_table(output):
    """The rows `dinam modes` prints: (frequency column as printed, Hz or None)."""
    rows, inside = [], False
    for line in output.splitlines():
        if line.startswith("mode  frequency (Hz)"):
            inside = True
            continue
        words = line.split()
        if not inside or not words or not words[0].isdigit():
            inside = False
            continue
        text = "0 (free)" if words[1:3] == ["0", "(free)"] else words[1]
        try:
            rows.append((text, float(text)))
        except ValueError:
            rows.append((text, None))
    return rows


def info_line(output, key):
    """The value of one line of `dinam info`'s table ("bars", "recommended", ...): its keys fill
    the first 16 columns."""
    for line in output.splitlines():
        if line[:16].rstrip() == key:
            return line[16:].strip()
    raise Broken(f"`dinam info` printed no '{key}' line")
