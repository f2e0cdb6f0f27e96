"""What the docs show users to type: every example that runs dinam is run as written, and what
the page says comes of it is checked; an example that cannot be run says why here."""
import re
import shlex
import subprocess

from promise import SOURCE, expect, png_size, promise

# Blocks of README.md and docs/*.md that name dinam but are not run here, each with why: a block
# is known by its page and its first line.
NOT_RUN = {
    ("README.md", "./scripts/install-deps.sh --render"):
        "the set-up itself, installing and building: CI runs the README's test command",
    ("docs/contributing.md", "./scripts/install-deps.sh --render"):
        "the README's set-up commands, repeated: CI runs them",
    ("docs/contributing.md", "cmake --build build --target bench_whole_run"):
        "a benchmark of minutes, outside the test run by design (contributing.md)",
    ("docs/contributing.md", "cmake --build build --target bench_force_costs"):
        "a benchmark, outside the test run by design",
    ("docs/commands.md", "build/dinam render SCENE [-o DIR]"):
        "a synopsis of each command's options, its names in capitals stand for the user's own",
    ("docs/motion-cache.md", "scripts/slurm-render.sh SCENE"):
        "the farm script's synopsis; tests/farm/slurm_farm_test.sh runs it on a Slurm cluster",
    ("docs/motion-cache.md", "slurm-render: dinam-simulate (job 6): COMPLETED"):
        "what a failed farm run prints, quoted; the farm test makes a render fail and checks it",
    ("docs/motion-cache.md", "scripts/slurm-render.sh /shared/proj/flag.yaml"):
        "a cluster's shared paths; the farm test runs the script on a cluster of its own",
}
# And those run by a promise below.
RUN = {
    ("docs/commands.md", "build/dinam simulate scenes/flag.yaml -o out/flag/cache"),
    ("docs/motion-cache.md", "build/dinam simulate scenes/flag.yaml -o out/flag/cache"),
    ("docs/getting-started.md", "build/dinam render curtain.yaml"),
    ("docs/snapshots.md", "# Once, and again whenever a change to the picture is meant: write the"),
}


def blocks():
    """(page, first line, text, language) of every fenced block of the docs."""
    for page in [SOURCE / "README.md"] + sorted((SOURCE / "docs").glob("*.md")):
        text = page.read_text()
        for match in re.finditer(r"```(\w*)\n(.*?)```", text, re.S):
            first = match.group(2).splitlines()[0].strip()
            yield str(page.relative_to(SOURCE)), first, match.group(2), match.group(1)


def block(page, first):
    for found_page, found_first, text, _ in blocks():
        if (found_page, found_first) == (page, first) or (
                found_page == page and found_first.startswith(first)):
            return text
    raise AssertionError(f"{page} has no block starting '{first}'")


def run_block(run, text):
    """Runs a shell block's commands as written, from the run's folder: `build/dinam` and `dinam`
    are the program under test, `scenes/` the shipped ones. Gives what each command printed."""
    printed = []
    commands = text.replace("\\\n", " ")
    for line in commands.splitlines():
        line = line.split("#")[0].strip() if not line.strip().startswith("#") else ""
        if not line:
            continue
        words = shlex.split(line)
        expect(words[0] in ("build/dinam", "dinam"), f"not a dinam command: {line}")
        arguments = [str(SOURCE / w) if w.startswith("scenes/") else w for w in words[1:]]
        finished = run.dinam(*arguments, ok=False)
        expect(finished.code in (0, 1) if words[1] == "snapshot" else finished.code == 0,
               f"`{line}` exited {finished.code}: {finished.tail()}")
        printed.append(finished.output)
    return printed


@promise(70, "every docs example that runs dinam is run by a promise here or says why not")
def every_docs_example_is_run_or_says_why(run):
    unaccounted = []
    for page, first, text, language in blocks():
        if language in ("sh", "bash", "") and "dinam" in text and "slurm-render:" not in first:
            key = next((k for k in RUN | set(NOT_RUN) if k[0] == page and first.startswith(k[1])),
                       None)
            if key is None:
                unaccounted.append(f"{page}: {first}")
        elif "slurm-render:" in first and (page, first) not in NOT_RUN:
            unaccounted.append(f"{page}: {first}")
    expect(not unaccounted, f"blocks neither run nor excused: {unaccounted}")
    return f"{len(RUN)} blocks run, {len(NOT_RUN)} excused with their reasons"


def movie_frames(path):
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                            "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", path],
                           capture_output=True, text=True)
    return int(probe.stdout.strip() or 0)


@promise(70, "docs/getting-started.md: the ten-line curtain renders to the 96 frames and the "
             "movie the page names")
def getting_started_curtain(run):
    page = (SOURCE / "docs/getting-started.md").read_text()
    scene = re.search(r"Save this as `curtain.yaml`:\n\n```yaml\n(.*?)```", page, re.S)
    expect(scene, "the page no longer shows curtain.yaml")
    run.scene("curtain.yaml", scene.group(1))
    run_block(run, block("docs/getting-started.md", "build/dinam render curtain.yaml"))
    named = re.search(r"writes `(out/curtain/frame_0001.png)`\n… `(frame_\d+.png)` and `(\S+)`",
                      page)
    expect(named, "the page no longer names the frames and the movie")
    last = named.group(2)
    frames = sorted(run.path("out/curtain").glob("frame_*.png"))
    expect(frames and frames[0].name == "frame_0001.png" and frames[-1].name == last,
           f"wrote {frames[0].name if frames else 'nothing'} … "
           f"{frames[-1].name if frames else ''}, the page says frame_0001.png … {last}")
    movie = run.path(named.group(3))
    expect(movie.is_file() and movie_frames(movie) == len(frames),
           f"{named.group(3)}: {'missing' if not movie.is_file() else movie_frames(movie)}")
    return f"{len(frames)} frames, {last} the last, and {named.group(3)}, as the page says"


def simulate_then_chunks(run, page, first):
    run_block(run, block(page, first))
    frames = sorted(run.path("out/flag").glob("frame_*.png"))
    movie = run.path("out/flag/flag.mp4")
    expect(len(frames) == 120 and movie.is_file() and movie_frames(movie) == 120,
           f"{len(frames)} frames, movie {movie.is_file()}")
    return f"120 frames drawn in chunks from one cache, and out/flag/flag.mp4 of 120"


@promise(70, "docs/commands.md: simulate once, render in two chunks, assemble the movie")
def commands_simulate_once_render_anywhere(run):
    return simulate_then_chunks(run, "docs/commands.md",
                                "build/dinam simulate scenes/flag.yaml -o out/flag/cache")


@promise(70, "docs/motion-cache.md: simulate once, render in three chunks, out/flag/flag.mp4")
def motion_cache_three_chunks(run):
    return simulate_then_chunks(run, "docs/motion-cache.md",
                                "build/dinam simulate scenes/flag.yaml -o out/flag/cache")


def same_warning(shown, printed):
    """Whether the warning the page shows is the one printed: the words and the pixel widths as
    shown, each percentage within 0.05 points (another Mesa build's rounding) and the suggested
    max_differing within a fifth."""
    measured = list(re.finditer(r"(\d+\.\d+)(?= %)|(?<=max_differing: )(\d+\.\d+)", shown))
    pattern, start = "", 0
    for number in measured:
        pattern += re.escape(shown[start:number.start()]) + r"(\d+\.\d+)"
        start = number.end()
    found = re.search(pattern + re.escape(shown[start:]), printed)
    if not found:
        return False
    return all(abs(float(p) - float(s.group())) <= (0.05 if s.group(1) else 0.2 * float(s.group()))
               for s, p in zip(measured, found.groups()))


@promise(70, "docs/snapshots.md: write the goldens (the rope warned of as the page shows), then "
             "compare with both reports")
def snapshots_page(run):
    update, _ = run_block(run, block("docs/snapshots.md", "# Once, and again whenever"))
    shown = block("docs/snapshots.md", "snapshot rope: warning:").strip()
    expect(same_warning(shown, update),
           f"the page shows\n{shown}\n--update printed\n{update.strip()}")
    goldens = sorted(p.name for p in run.path("tests/golden").glob("*.png"))
    reports = [run.path(name) for name in ("snapshots.xml", "snapshots.html")]
    expect(len(goldens) == 6 and all(r.is_file() for r in reports),
           f"goldens {goldens}; reports {[r.is_file() for r in reports]}")
    return f"{len(goldens)} goldens written, then snapshots.xml and snapshots.html"
