"""The paper's model against closed-form mechanics, through `simulate` and its files."""
import csv
import math

from promise import expect, near, promise, read_pc2


def crossings(times, values):
    """The instants where `values` changes sign, interpolated linearly."""
    found = []
    for k in range(1, len(values)):
        a, b = values[k - 1], values[k]
        if a == 0 or a * b < 0:
            found.append(times[k - 1] + (times[k] - times[k - 1]) * a / (a - b))
    return found


@promise(2, "a mass on a spring oscillates at √(k/m) within 0.5 %")
def mass_on_a_spring(run):
    # One bar of 1 m hung from a pin: its free node has half the bar's mass, m = ρ A L / 2, on
    # the spring k = E A / L, so ω² = 2 E / (ρ L²) = 200 s⁻², a period of 0.4443 s. It starts
    # at the bar's rest length and bobs about m g / k below it.
    scene = run.scene("spring.yaml", """version: 1
duration: 4.5
fps: 200
ground: {contact: false, visible: false}
objects:
  - name: spring
    mesh: {polyline: {points: [[0, 0, 2], [0, 0, 1]]}}
    material: {density: 1000, youngs_modulus: 1.0e5, radius: 0.01}
    pinned: {indices: [0]}
""")
    run.dinam("simulate", scene, "-o", "cache", "--quiet")
    frames = read_pc2(run.path("cache/spring.pc2"))
    g, rest_below = 9.81, 1000 * 9.81 * 1.0 ** 2 / (2 * 1.0e5)  # m g / k = ρ g L² / 2E
    z = [f[1][2] - (1.0 - rest_below) for f in frames]  # about the static equilibrium
    times = [k / 200 for k in range(len(frames))]
    zeros = crossings(times, z)
    expect(len(zeros) >= 10, f"{len(zeros)} crossings of the equilibrium in 4.5 s")
    period = 2 * (zeros[-1] - zeros[0]) / (len(zeros) - 1)
    expected = 2 * math.pi / math.sqrt(2 * 1.0e5 / 1000)
    expect(near(period, expected, 0.005), f"period {period:.5f} s against {expected:.5f} s")
    return f"period {period:.5f} s against 2π/√(k/m) = {expected:.5f} s"


@promise(3, "an undamped swinging chain keeps its energy within 0.1 % over 10⁵ steps")
def chain_keeps_its_energy(run):
    scene = run.scene("chain.yaml", """version: 1
duration: 8
fps: 20
ground: {contact: false, visible: false}
objects:
  - name: chain
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e9, radius: 0.005}
    pinned: {indices: [0]}
""")
    steps = run.dinam("info", scene).output
    run.dinam("simulate", scene, "-o", "cache", "--energy", "--quiet")
    rows = list(csv.DictReader(open(run.path("cache/energy.csv"))))
    start = float(rows[0]["total_J"])
    peak_kinetic = max(float(r["kinetic_J"]) for r in rows)
    drift = max(abs(float(r["total_J"]) - start) for r in rows) / peak_kinetic
    count = int(next(l for l in steps.splitlines() if l.startswith("steps in all")).split()[3])
    expect(count >= 100000, f"{count} steps, 10⁵ asked for")
    # Of the peak kinetic energy: the total's own size depends on where the height is measured.
    expect(drift <= 1e-3, f"energy balance off by {100 * drift:.3g} % of the peak kinetic energy")
    return f"{count} steps, balance within {100 * drift:.2g} % of the peak kinetic energy"


@promise(30, "settle by Newton: a clamped cantilever sags w L⁴ / 8 E I under its weight")
def cantilever_sags_under_its_weight(run):
    points = ", ".join(f"[{k / 40}, 0, 1]" for k in range(41))
    scene = run.scene("cantilever.yaml", f"""version: 1
duration: 0.05
fps: 20
settle: {{method: newton}}
ground: {{contact: false, visible: false}}
objects:
  - name: beam
    mesh: {{polyline: {{points: [{points}]}}, weld: off}}
    material: {{density: 7850, youngs_modulus: 2.0e9, area: 1.0e-4, area_moment: 4.0e-8}}
    pinned: {{indices: [0], clamped: true}}
    torsion: false
""")
    finished = run.dinam("simulate", scene, "-o", "cache")
    tip = read_pc2(run.path("cache/beam.pc2"))[0][40]
    w, ei = 7850 * 1.0e-4 * 9.81, 2.0e9 * 4.0e-8  # N/m and N·m²
    expected = w * 1.0 ** 4 / (8 * ei)
    sag = 1.0 - tip[2]
    # Second order in the bar count: 40 bars leave it within 0.5 %; small against L (0.12 %),
    # so the linear theory holds.
    expect(near(sag, expected, 0.005) and "Newton's method" in finished.output,
           f"tip sags {1000 * sag:.4f} mm against {1000 * expected:.4f} mm; "
           f"{finished.tail(1)}")
    return f"tip sags {1000 * sag:.4f} mm against w L⁴ / 8 E I = {1000 * expected:.4f} mm"


@promise(3, "a fast impact does not tunnel through the ground")
def fast_impact_stays_above_ground(run):
    scene = run.scene("drop.yaml", """version: 1
duration: 1
fps: 100
objects:
  - name: bar
    mesh: {polyline: {points: [[0, 0, 0.3], [0.2, 0, 0.3]], segments: 4}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.005}
    initial_velocity: [0, 0, -40]
""")
    run.dinam("simulate", scene, "-o", "cache", "--quiet")
    frames = read_pc2(run.path("cache/bar.pc2"))
    lowest = min(p[2] for f in frames for p in f)
    last = min(p[2] for p in frames[-1])
    # The ground's penalty lets a node in by a share of its radius at most, never through.
    expect(lowest > -0.005 and last > -0.005,
           f"lowest node at z = {1000 * lowest:.2f} mm, {1000 * last:.2f} mm at the end")
    return f"thrown down at 40 m/s: lowest node at z = {1000 * lowest:.3f} mm"
