"""Simulate once, render anywhere: the motion cache, the USD stage, the page that plays it."""
import filecmp
import re

from promise import SOURCE, expect, promise


@promise(11, "frames drawn in chunks from a cache are byte for byte those of one whole render")
def chunks_from_a_cache_equal_a_whole_render(run):
    scene = SOURCE / "scenes/flag.yaml"
    size = ("--size", "320x180", "--movie", "none", "--quiet")
    run.dinam("render", scene, "-o", "whole", *size)
    run.dinam("simulate", scene, "-o", "cache", "--quiet")
    run.dinam("render", scene, "--cache", "cache", "--frames", "1-60", "-o", "chunks", *size)
    run.dinam("render", scene, "--cache", "cache", "--frames", "61-120", "-o", "chunks", *size)
    whole = sorted(p.name for p in run.path("whole").glob("frame_*.png"))
    chunks = sorted(p.name for p in run.path("chunks").glob("frame_*.png"))
    expect(whole == chunks and len(whole) == 120,
           f"{len(whole)} frames whole, {len(chunks)} in chunks")
    differ = [n for n in whole if not filecmp.cmp(run.path("whole") / n, run.path("chunks") / n,
                                                  shallow=False)]
    expect(not differ, f"{len(differ)} frames differ, the first {differ[:1]}")
    return "120 frames in two chunks from one cache, each byte for byte the whole render's"


@promise(32, "the cache's USD stage keeps the UV seams (face-varying st) and a material per "
             "object with its colour")
def usd_keeps_seams_and_material(run):
    run.dinam("simulate", SOURCE / "scenes/flag.yaml", "-o", "cache", "--quiet")
    stages = list(run.path("cache").glob("*.usda"))
    expect(stages, "no USD stage in the cache")
    text = stages[0].read_text()
    seams = re.search(r'texCoord2f\[\] primvars:st = \[.*?\] \(\s*interpolation = "faceVarying"',
                      text, re.S)
    material = re.search(r'uniform token info:id = "UsdPreviewSurface"', text)
    colour = re.search(r"color3f inputs:diffuseColor = \(([^)]*)\)", text)
    expect(seams and material and colour,
           f"in {stages[0].name}: face-varying st {bool(seams)}, UsdPreviewSurface "
           f"{bool(material)}, diffuse colour {bool(colour)}")
    return f"face-varying st, UsdPreviewSurface, diffuseColor ({colour.group(1)})"


@promise(32, "`dinam view` writes one self-contained page that plays the cache with WebGL")
def view_writes_a_webgl_page(run):
    run.dinam("simulate", SOURCE / "scenes/flag.yaml", "-o", "cache", "--quiet")
    run.dinam("view", "cache", "-o", "flag.html")
    page = run.path("flag.html").read_text()
    external = re.findall(r'(?:src|href)\s*=\s*"(https?:[^"]*)"', page)
    expect("WebGLRenderer" in page and not external,
           f"WebGLRenderer in the page: {'WebGLRenderer' in page}; fetched from elsewhere: "
           f"{external[:2]}")
    return f"a WebGL page of {len(page.encode()) // 1024} KiB that fetches nothing"
