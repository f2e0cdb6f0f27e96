"""Objects tied to each other: the paper's flag on its pole, a rope on a hook."""
import math
import re

from promise import SOURCE, expect, promise, read_pc2

POLE_RADIUS = 0.025  # m, scenes/flag.yaml's pole


def mesh_of(path):
    """An OBJ file of the cache: its vertices and the bars its faces and lines make."""
    vertices, bars = [], set()
    for line in path.read_text().splitlines():
        words = line.split()
        if words and words[0] == "v":
            vertices.append(tuple(map(float, words[1:4])))
        elif words and words[0] in ("f", "l"):
            ids = [int(w.split("/")[0]) - 1 for w in words[1:]]
            ends = zip(ids, ids[1:] + ids[:1]) if words[0] == "f" else zip(ids, ids[1:])
            bars |= {(min(a, b), max(a, b)) for a, b in ends}
    return vertices, bars


def distance_from_pole(p, q):
    """The distance of segment pq from the pole's axis (the z axis), and the height there."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    length = dx * dx + dy * dy
    t = 0.0 if length == 0.0 else max(0.0, min(1.0, -(p[0] * dx + p[1] * dy) / length))
    return math.hypot(p[0] + t * dx, p[1] + t * dy), p[2] + t * (q[2] - p[2])


@promise(71, "the paper's flag is tied to its pole: its tied nodes stay where they are tied, and "
             "no other part of it passes through the pole over its 120 frames")
def paper_flag_tied_to_its_pole(run):
    run.dinam("simulate", SOURCE / "scenes/flag.yaml", "-o", "cache", "--quiet")
    start, bars = mesh_of(run.path("cache/flag.obj"))
    frames = read_pc2(run.path("cache/flag.pc2"))
    expect(len(frames) == 120, f"{len(frames)} frames")
    # The scene's boxes: the nodes on the pole (three of each of the five loops, the halyard's two
    # ends) and the loops' other two nodes each: 27.
    tied = [i for i, (x, y, z) in enumerate(start)
            if (abs(x) <= 0.032 and abs(y) <= 0.032) or
            (0.032 <= x <= 0.05 and abs(y) <= 0.032 and 2.55 <= z <= 3.75)]
    expect(len(tied) == 27, f"{len(tied)} tied nodes, not the scene's 27")
    # The pole is pinned: a tied node's place relative to its point on the pole is where it
    # settled (frame 1), which the rigid tie holds within its give (k at half the structure's
    # highest frequency: the flag's weight moves the ties by millimetres).
    give = max(math.dist(frame[i], frames[0][i]) for frame in frames for i in tied)
    expect(give < 0.003, f"a tied node moved {1000 * give:.2f} mm from where it is tied")
    # The bars that cross the pole's section at the start (the loops' chords, where they are
    # tied: their contact is left out) aside, no bar comes nearer the axis than the pole's
    # surface, less what the penalty lets a rope sink into it.
    crossing = {b for b in bars
                if distance_from_pole(frames[0][b[0]], frames[0][b[1]])[0] < POLE_RADIUS + 0.0015}
    closest, frame_of = min(
        (distance_from_pole(frame[a], frame[b])[0], k)
        for k, frame in enumerate(frames) for a, b in bars - crossing
        if distance_from_pole(frame[a], frame[b])[1] <= 4.0)
    expect(closest > POLE_RADIUS - 0.001,
           f"a bar came {1000 * closest:.2f} mm from the pole's axis (frame {frame_of + 1}), "
           f"inside its {1000 * POLE_RADIUS:.0f} mm radius")
    return (f"{len(tied)} tied nodes within {1000 * give:.2f} mm of where they are tied over 120 "
            f"frames; the nearest of the other bars {1000 * closest:.2f} mm from the pole's axis "
            f"(its radius {1000 * POLE_RADIUS:.0f} mm), at frame {frame_of + 1}")


@promise(71, "a rope tied to a hook where it touches it runs with contact on, and hangs from it")
def rope_tied_on_a_hook(run):
    hook = """version: 1
duration: 2
fps: 20
gravity: [0, 0, -9.81]
ground: {height: 0}
contact: {objects: true}
objects:
  - name: hook
    mesh: {polyline: {points: [[0, -0.1, 1.5], [0, 0.1, 1.5]], segments: 2}}
    role: collider
    contact: {radius: 0.01}
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1.5], [0.8, 0, 1.5]], segments: 16}}
    material: {preset: hemp_rope}
"""
    placed = run.dinam("simulate", run.scene("placed.yaml", hook), "-o", "placed", "--quiet",
                       ok=False)
    expect(placed.code != 0 and "overlap in the starting positions" in placed.output,
           f"a rope merely placed on the hook: exit {placed.code}, {placed.tail(1)}")
    tied = hook + "    attach: [{nodes: {indices: [0]}, to: hook}]\n"
    run.dinam("simulate", run.scene("tied.yaml", tied), "-o", "cache", "--quiet")
    frames = read_pc2(run.path("cache/rope.pc2"))
    held = max(math.dist(frame[0], (0.0, 0.0, 1.5)) for frame in frames)
    # Released level, the 0.8 m rope swings down under its end: its lowest point reaches about
    # 0.7 m.
    lowest = min(p[2] for frame in frames for p in frame)
    expect(held < 1e-3 and lowest < 0.75,
           f"the tied end moved {1000 * held:.3f} mm; the rope's lowest point {lowest:.2f} m")
    pairs = re.search(r"(\d+) contact pairs", placed.output).group(1)
    return (f"placed: refused ({pairs} pairs overlap); tied: its end within {1000 * held:.3f} mm "
            f"of the hook, swinging down to {lowest:.2f} m")
