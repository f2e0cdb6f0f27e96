"""Outputs that cannot be turned against the user."""
import os

from promise import expect, promise

ROPE = """version: 1
duration: 0.2
fps: 10
image: {width: 160, height: 90}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {preset: hemp_rope}
    pinned: {indices: [0]}
"""


@promise(35, "a symbolic link planted where a frame goes is never written through")
def planted_link_never_followed(run):
    scene = run.scene("rope.yaml", ROPE)
    victim = run.path("victim.txt")
    victim.write_text("the user's own file\n")
    run.path("out").mkdir()
    os.symlink(victim, run.path("out/frame_0001.png"))
    finished = run.dinam("render", scene, "-o", "out", "--movie", "none", "--quiet", ok=False)
    expect(victim.read_text() == "the user's own file\n",
           f"the link's target was written through (exit {finished.code})")
    frame = run.path("out/frame_0001.png")
    written = not frame.is_symlink() and frame.is_file()
    expect(written or finished.code == 2,
           f"exit {finished.code}, frame_0001.png a link still: {finished.tail()}")
    return (f"exit {finished.code}; the target untouched, frame_0001.png "
            + ("a new regular file" if written else "refused"))


@promise(15, "an output folder that cannot be written is exit 2, naming the path given")
def unwritable_output_is_refused(run):
    scene = run.scene("rope.yaml", ROPE)
    run.path("taken").write_text("a file where the folder would go\n")
    finished = run.dinam("render", scene, "-o", "taken/frames", ok=False)
    expect(finished.code == 2 and "taken/frames" in finished.output,
           f"exit {finished.code}: {finished.tail()}")
    return finished.output.strip().splitlines()[-1][:110]
