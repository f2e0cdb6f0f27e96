"""Scene file to movie, as the README's first command runs it; the paper's flag; bad input."""
import json
import subprocess

from promise import SOURCE, expect, info_line, png_size, promise


@promise(2, "`dinam render scenes/flag.yaml` writes 120 frames at 1280×720 and a 6 s movie "
            "(H.264, tagged BT.709: issue 32)")
def flag_renders_to_a_movie(run):
    run.dinam("render", SOURCE / "scenes/flag.yaml", "-o", "flag", "--quiet")
    frames = sorted(run.path("flag").glob("frame_*.png"))
    expect(len(frames) == 120, f"{len(frames)} frames written, 120 expected")
    sizes = {png_size(f) for f in (frames[0], frames[-1])}
    expect(sizes == {(1280, 720)}, f"frames of {sizes}, 1280×720 expected")
    probe = subprocess.run(
        ["ffprobe", "-v", "error", "-show_entries",
         "stream=codec_name,width,height,nb_frames,duration,color_space,color_transfer,"
         "color_primaries,pix_fmt", "-of", "json", run.path("flag/flag.mp4")],
        capture_output=True, text=True)
    expect(probe.returncode == 0, f"ffprobe could not read flag.mp4: {probe.stderr.strip()}")
    stream = json.loads(probe.stdout)["streams"][0]
    seen = (stream["codec_name"], stream["width"], stream["height"], stream["nb_frames"],
            float(stream["duration"]), stream["pix_fmt"], stream.get("color_space"),
            stream.get("color_transfer"), stream.get("color_primaries"))
    expect(seen == ("h264", 1280, 720, "120", 6.0, "yuv420p", "bt709", "bt709", "bt709"),
           f"the movie is {seen}")
    return "120 frames at 1280×720, flag.mp4: H.264 1280×720, 120 frames, 6.0 s, BT.709"


@promise(5, "the paper's flag: 245 nodes and 579 bars, 12 000 steps of 0.5 ms")
def papers_flag_as_the_paper_has_it(run):
    output = run.dinam("info", SOURCE / "scenes/flag.yaml").output
    flag = next((l.strip() for l in output.splitlines() if l.strip().startswith("flag ")), "")
    steps = info_line(output, "steps")
    step = info_line(output, "time step")
    expect(flag.split()[1:5] == ["245", "nodes,", "579", "bars"],
           f"info says '{flag}' for the flag")
    expect(steps.startswith("12000 over the 6 s"), f"info says steps '{steps}'")
    expect(step.startswith("0.0005 s"), f"info says time step '{step}'")
    return f"{flag}; {steps.split(' (')[0]} of {step.split(' (')[0]}"


@promise(31, "a misspelt key is an error at its file:line:column with 'did you mean', exit 2, "
             "and nothing written")
def misspelt_key_is_refused_at_its_line(run):
    scene = run.scene("typo.yaml", """version: 1
duration: 1
setle: {method: newton}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {preset: hemp_rope}
""")
    finished = run.dinam("render", scene, "-o", "out", ok=False)
    expect(finished.code == 2, f"exit {finished.code}, 2 expected: {finished.tail()}")
    expect(f"{scene}:3:1: error: unknown key 'setle'" in finished.output
           and "did you mean 'settle'?" in finished.output,
           f"printed '{finished.tail(1)}'")
    expect(not run.path("out").exists(), "the output folder was made for a refused scene")
    return finished.output.strip().splitlines()[-1][:120]


@promise(31, "a unit slip (a wire radius of 1 m on a cloth) is warned of at its line")
def unit_slip_warned_at_its_line(run):
    scene = run.scene("cloth.yaml", """version: 1
duration: 0.1
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 10, rows: 10}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 1}
    pinned: {indices: [0]}
""")
    output = run.dinam("info", scene).output
    warning = next((l for l in output.splitlines() if "warning" in l), "")
    expect(warning.startswith(f"{scene}:6:") and "'radius' is in metres" in warning,
           f"warned '{warning or 'nothing'}'")
    return warning[len(str(scene)):][:110]
