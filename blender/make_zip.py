"""Packs the add-on for Blender's Preferences > Add-ons > Install: a zip holding the package folder
(dinam_blender/*.py), nothing else (no __pycache__), with fixed dates so the zip is the same on
every build.

    python3 blender/make_zip.py blender/dinam_blender OUT.zip
"""
import os
import sys
import zipfile

source, out = sys.argv[1:]
package = os.path.basename(os.path.normpath(source))
with zipfile.ZipFile(out + ".part", "w", zipfile.ZIP_DEFLATED) as archive:
    for name in sorted(os.listdir(source)):
        if name.endswith(".py"):
            info = zipfile.ZipInfo(f"{package}/{name}", date_time=(2026, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            with open(os.path.join(source, name), "rb") as f:
                archive.writestr(info, f.read())
os.replace(out + ".part", out)
