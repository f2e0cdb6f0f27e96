"""`dinam info`: cheap at any size, and a recommendation that holds."""
from promise import expect, info_line, promise


@promise(57, "`info` on a cloth of a million bars stays under 1 GB")
def info_at_a_million_bars(run):
    # 577 × 577 cells, each cut in two: 999 941 bars.
    scene = run.scene("cloth.yaml", """version: 1
duration: 1
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 577, rows: 577, diagonals: one}}
    material: {preset: cotton}
    pinned: {indices: [0]}
""")
    finished = run.dinam("info", scene, timeout=120)
    bars = int(info_line(finished.output, "bars").split()[0])
    expect(bars >= 999000, f"{bars} bars")
    peak_mb = finished.max_rss_kb / 1024
    expect(peak_mb < 1024, f"info held {peak_mb:.0f} MB at its peak")
    return f"{bars} bars: info's peak {peak_mb:.0f} MB"


@promise(53, "`info` recommends BDF2 for a swinging steel cable, where backward Euler damps "
             "the swing away")
def info_recommends_bdf2_for_a_swinging_cable(run):
    scene = run.scene("cable.yaml", """version: 1
duration: 3
ground: {contact: false, visible: false}
objects:
  - name: cable
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 100}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.001}
    pinned: {indices: [0]}
""")
    recommended = info_line(run.dinam("info", scene).output, "recommended")
    expect(recommended.startswith("integrator: implicit_bdf2"), f"info recommends '{recommended}'")
    return recommended[:100]
