"""Natural modes through the table `dinam modes` prints."""
import math

from promise import SOURCE, expect, modes_table, near, promise

J0_ZEROS = (2.404826, 5.520078, 8.653728)


@promise(52, "a hanging chain preset sways within 1 % of the hanging chain, first three modes")
def chain_sways_as_the_hanging_chain(run):
    scene = run.scene("chain.yaml", """version: 1
duration: 0.1
ground: {contact: false, visible: false}
objects:
  - name: chain
    mesh: {polyline: {points: [[0, 0, 2], [0, 0, 1]], segments: 40}}
    material: {preset: chain}
    pinned: {indices: [0]}
""")
    rows = modes_table(run.dinam("modes", scene, "--count", 6, "-o", "modes").output)
    expect(len(rows) == 6, f"{len(rows)} rows printed, 6 asked for")
    printed = []
    for n, zero in enumerate(J0_ZEROS):
        expected = zero / 2 * math.sqrt(9.81 / 1.0) / (2 * math.pi)  # (j₀,ₙ/2) √(g/L) / 2π
        for text, hz in rows[2 * n:2 * n + 2]:  # each sway twice, in x and in y
            expect(hz is not None and near(hz, expected, 0.01),
                   f"mode {n + 1} printed as '{text}', the hanging chain's is {expected:.4f} Hz")
        printed.append(rows[2 * n][0])
    return "modes at " + ", ".join(printed) + " Hz (chain: 0.5994, 1.3759, 2.1570)"


def table_rows(text):
    """The rows of a modes table, each as its words, from its header on."""
    lines = text[text.index("mode  frequency (Hz)"):].splitlines()
    rows = []
    for line in lines[1:]:
        if not line.strip() or not line.split()[0].isdigit():
            break
        rows.append(line.split())
    return rows


@promise(30, "the shaken tower's modes table, as `dinam modes` prints it, is the one "
             "docs/commands.md shows, to every digit")
def tower_sways_as_documented(run):
    # The table as docs/commands.md prints it, read from the page itself.
    page = (SOURCE / "docs/commands.md").read_text()
    documented = table_rows(page[page.index("## How a structure sways"):])
    expect(len(documented) >= 2, "docs/commands.md shows no table of the tower's modes")
    finished = run.dinam("modes", SOURCE / "scenes/shaken_tower.yaml", "--count",
                         len(documented), "-o", "m")
    printed = table_rows(finished.output)
    expect(printed == documented, f"printed {printed}, the page shows {documented}")
    return (f"{len(printed)} rows as the page shows them: sways at {printed[0][1]} and "
            f"{printed[1][1]} Hz")


@promise(13, "a clamped cantilever's first frequency within 0.3 % of β₁L = 1.8751 at 40 bars")
def clamped_cantilever_first_frequency(run):
    points = ", ".join(f"[{k / 40}, 0, 1]" for k in range(41))
    scene = run.scene("cantilever.yaml", f"""version: 1
duration: 0.1
gravity: [0, 0, 0]
ground: {{contact: false, visible: false}}
objects:
  - name: beam
    mesh: {{polyline: {{points: [{points}]}}, weld: off}}
    material: {{density: 7850, youngs_modulus: 2.0e11, area: 1.0e-4, area_moment: 4.0e-8}}
    pinned: {{indices: [0], clamped: true}}
    torsion: false
""")
    rows = modes_table(run.dinam("modes", scene, "--count", 2, "-o", "modes").output)
    # Euler–Bernoulli: f₁ = (β₁L)² √(EI / ρA) / (2π L²), E I = 8000 N·m², ρ A = 0.785 kg/m.
    expected = 1.875104 ** 2 * math.sqrt(8000 / 0.785) / (2 * math.pi)
    hz = rows[0][1] if rows else None
    expect(hz is not None and near(hz, expected, 0.003),
           f"first mode printed as '{rows[0][0] if rows else 'nothing'}', Euler–Bernoulli's is "
           f"{expected:.3f} Hz")
    return f"first mode {rows[0][0]} Hz against {expected:.3f} ({100 * (hz / expected - 1):+.2f} %)"


@promise(57, "a body nothing holds has six free motions, printed as such, not as unstable")
def free_body_six_free_motions(run):
    scene = run.scene("tetra.yaml", f"""version: 1
duration: 0.1
gravity: [0, 0, 0]
ground: {{contact: false, visible: false}}
objects:
  - name: frame
    mesh: {{file: {SOURCE / 'tests/data/tetra.ply'}}}
    material: {{preset: steel_wire, radius: 0.01}}
""")
    rows = modes_table(run.dinam("modes", scene, "--count", 7, "-o", "modes").output)
    free = [text for text, _ in rows[:6] if text == "0 (free)"]
    expect(len(free) == 6 and rows[6][1] is not None and rows[6][1] > 0,
           f"printed {[r[0] for r in rows]}: six '0 (free)' rows, then a frequency, expected")
    return f"six free motions, then {rows[6][0]} Hz"
