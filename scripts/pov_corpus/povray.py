# SPDX-License-Identifier: MIT
"""POV-Ray's renders of the sample scenes, the judge of how a file should look and how long it may
take, cached between runs (one POV-Ray run of the corpus takes about an hour on two cores).

Each scene is rendered as `povray +A0.3` renders it by default on Debian: the file's own settings,
adaptive anti-aliasing (method 1, threshold 0.3), POV-Ray's gamma rules, PNG output. `radiosity_off`
renders at quality 8 (+Q8), which turns off radiosity, photons and media alike."""
import glob
import json
import os
import shutil
import subprocess

from . import runner, scenes

POVRAY = "povray"


def version():
    """POV-Ray's version line, or None when it is not installed."""
    if not shutil.which(POVRAY):
        return None
    p = subprocess.run([POVRAY, "--version"], capture_output=True, text=True, errors="replace")
    for line in (p.stdout + p.stderr).split("\n"):
        if "POV-Ray" in line or "Persistence of Vision" in line:
            return line.strip()
    return "povray"


def cache_folder(root, width, height, radiosity_off=False):
    return os.path.join(root, "%dx%d%s" % (width, height, "-q8" if radiosity_off else ""))


def render(scene, rel, cache, width, height, seconds, threads=2, radiosity_off=False):
    """POV-Ray's image of `scene` (rel: its path under the examples), from the cache when there.
    Returns {code, cpu, wall, image (path or None), stderr_tail}."""
    image = os.path.join(cache, rel[:-4] + ".png")
    meta = image[:-4] + ".json"
    if os.path.exists(meta):
        with open(meta) as f:
            return json.load(f)
    os.makedirs(os.path.dirname(image), exist_ok=True)
    out_dir = image[:-4] + ".out"
    shutil.rmtree(out_dir, ignore_errors=True)
    os.makedirs(out_dir)
    cmd = [POVRAY, "-D", "-V", "-GA", "+I" + os.path.basename(scene), "+O" + os.path.join(out_dir, "frame.png"),
           "+FN8", "+W%d" % width, "+H%d" % height, "+A0.3", "+WT%d" % threads]
    cmd += ["+Q8"] if radiosity_off else []
    cmd += scenes.povray_options(scene)
    r = runner.run(cmd, os.path.dirname(scene), seconds)
    frames = sorted(glob.glob(os.path.join(out_dir, "*.png")))
    ok = r["code"] == 0 and frames
    if ok:
        os.replace(frames[0], image)
    shutil.rmtree(out_dir, ignore_errors=True)
    result = {"code": r["code"], "cpu": r["cpu"], "wall": r["wall"], "image": image if ok else None,
              "stderr_tail": "\n".join(r["stderr"].strip().split("\n")[-8:])}
    with open(meta, "w") as f:
        json.dump(result, f, indent=1)
    return result
