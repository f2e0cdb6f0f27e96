"""Snapshot tests as users put them in their own CI."""
import xml.etree.ElementTree as ElementTree

from promise import expect, promise

BANNER = """version: 1
name: banner
duration: 1
fps: 10
camera: {{position: [0.5, -2.2, 1.2], look_at: [0.5, 0, 1.0], fov: 40}}
objects:
  - name: banner
    mesh:
      grid: {{width: 1, height: 0.6, columns: 10, rows: 6, diagonals: one}}
      rotation: [90, 0, 0]
      translation: [0, 0, 1.3]
    material: {{preset: canvas}}
    pinned: {{box: {{min: [-0.01, -0.01, 1.29], max: [1.01, 0.01, 1.31]}}}}
    color: {colour}
"""


@promise(54, "a snapshot passes the same scene, fails a changed colour with its images and a "
             "JUnit report CI reads")
def snapshot_catches_a_changed_colour(run):
    scene = run.scene("banner.yaml", BANNER.format(colour="[0.8, 0.2, 0.2]"))
    run.dinam("snapshot", scene, "--golden", "golden", "--frames", "1,last", "--update",
              "--quiet")
    same = run.dinam("snapshot", scene, "--golden", "golden", "--frames", "1,last",
                     "--junit", "same.xml", "-o", "same", ok=False)
    expect(same.code == 0, f"the unchanged scene: exit {same.code}: {same.tail()}")
    scene.write_text(BANNER.format(colour="[0.2, 0.2, 0.8]"))
    changed = run.dinam("snapshot", scene, "--golden", "golden", "--frames", "1,last",
                        "--junit", "changed.xml", "-o", "changed", ok=False)
    expect(changed.code == 1, f"the banner turned blue: exit {changed.code}: {changed.tail()}")
    images = sorted(p.name for p in run.path("changed").rglob("*.png"))
    expect(any("diff" in n for n in images) and any("actual" in n for n in images),
           f"written for the changed frames: {images}")
    report = ElementTree.parse(run.path("changed.xml")).getroot()
    failures = [case for case in report.iter("testcase") if case.find("failure") is not None]
    expect(len(failures) == 2, f"the JUnit report has {len(failures)} failing frames of 2")
    return f"unchanged: exit 0; blue for red: exit 1, {len(images)} images, 2 failures in JUnit"
