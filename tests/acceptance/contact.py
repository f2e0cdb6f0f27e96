"""Objects that touch: a wire never lets another through."""
from promise import expect, promise, read_pc2


@promise(12, "a wire thrown at 10 m/s onto another, crosswise, never passes through it")
def wire_never_passes_through_wire(run):
    # A steel wire held at both ends along x at z = 1, and a second across it along y, 5 cm
    # above, thrown down at 10 m/s: it must land on the first and stay above it where they
    # cross (both of 5 mm radius: their axes at least about 1 cm apart).
    scene = run.scene("wires.yaml", """version: 1
duration: 0.4
fps: 200
gravity: [0, 0, -9.81]
ground: {contact: false, visible: false}
contact: {objects: true}
objects:
  - name: held
    mesh: {polyline: {points: [[-0.5, 0, 1], [0.5, 0, 1]], segments: 20}}
    material: {preset: steel_wire, radius: 0.005}
    pinned: {indices: [0, 20]}
  - name: thrown
    mesh: {polyline: {points: [[0.013, -0.3, 1.05], [0.013, 0.3, 1.05]], segments: 12}}
    material: {preset: steel_wire, radius: 0.005}
    initial_velocity: [0, 0, -10]
""")
    run.dinam("simulate", scene, "-o", "cache", "--quiet")
    held = read_pc2(run.path("cache/held.pc2"))
    thrown = read_pc2(run.path("cache/thrown.pc2"))
    middle = 6  # the thrown wire's node over the crossing
    gaps = []
    for h, t in zip(held, thrown):
        # The held wire's height under the thrown wire's middle node (nearest of its nodes).
        under = min(h, key=lambda p: abs(p[0] - t[middle][0]))
        gaps.append(t[middle][2] - under[2])
    expect(min(gaps) > 0 and gaps[-1] > 0,
           f"the thrown wire's middle came to {1000 * min(gaps):.2f} mm above the held one "
           f"(below it: passed through), {1000 * gaps[-1]:.2f} mm at the end")
    return f"thrown at 10 m/s: axes at least {1000 * min(gaps):.2f} mm apart where they cross"
