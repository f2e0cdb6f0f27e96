"""The implicit integrators: BDF2 keeps a swing as central differences have it."""
import math

from promise import expect, promise, read_pc2

CABLE = """version: 1
duration: 3
fps: 24
integrator: {integrator}
ground: {{contact: false, visible: false}}
objects:
  - name: cable
    mesh: {{polyline: {{points: [[0, 0, 2.2], [2, 0, 2.2]], segments: 100}}}}
    material: {{density: 7850, youngs_modulus: 2.0e11, radius: 0.001}}
    pinned: {{indices: [0]}}
"""


@promise(53, "BDF2 swings a 2 m steel cable as central differences do, its tip within 2 cm")
def bdf2_keeps_a_cables_swing(run):
    tips = {}
    for integrator in ("central_difference", "implicit_bdf2"):
        scene = run.scene(f"{integrator}.yaml", CABLE.format(integrator=integrator))
        run.dinam("simulate", scene, "-o", integrator, "--quiet")
        tips[integrator] = read_pc2(run.path(f"{integrator}/cable.pc2"))[-1][-1]
    apart = math.dist(tips["central_difference"], tips["implicit_bdf2"])
    expect(apart <= 0.02, f"BDF2's tip {100 * apart:.1f} cm from central differences' at 3 s")
    return (f"tip at z = {tips['implicit_bdf2'][2]:.3f} m (BDF2) and "
            f"{tips['central_difference'][2]:.3f} m (central differences), {1000 * apart:.1f} mm "
            "apart at 3 s")
