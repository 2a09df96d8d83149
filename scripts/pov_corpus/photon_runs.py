# SPDX-License-Identifier: MIT
"""photon's side of the corpus: `photon check` and `photon render` of one scene."""
import os
import re

from . import runner, scenes

DIAGNOSTIC = re.compile(r"^(?P<loc>[^\s:][^:]*:\d+:\d+): (?P<sev>warning|error): (?P<msg>.*)$")


def diagnostics(stderr):
    """(severity, location, message) of every located warning and error photon printed."""
    out = []
    for line in stderr.split("\n"):
        m = DIAGNOSTIC.match(line)
        if m:
            out.append((m.group("sev"), m.group("loc"), m.group("msg")))
    return out


def warning_kind(message):
    """A warning without its particulars (numbers, quoted file names), for counting by kind."""
    kind = re.sub(r"\"[^\"]*\"", '"..."', message)
    kind = re.sub(r"-?\d+(\.\d+)?(e[-+]?\d+)?", "N", kind)
    kind = re.sub(r" at (\S+:)?N:N", " at ...", kind)
    return kind


def first_error(stderr):
    for sev, loc, msg in diagnostics(stderr):
        if sev == "error":
            return loc, msg
    lines = [l for l in stderr.split("\n") if l.strip()]
    return "", (lines[-1] if lines else "no message")


def check(photon, scene, seconds=120):
    """`photon check` of the scene from its own folder: {code, stderr, check_seconds, mode (the
    mode a render with the defaults would use, when it passes), indirect (its plan has indirect
    light)}."""
    r = runner.run([photon, "check", os.path.basename(scene)] + scenes.photon_options(scene),
                   os.path.dirname(scene), seconds, keep_stdout=True)
    out = r.get("stdout", "")
    m = re.search(r"^settings .*?, mode ([\w-]+)", out, re.M)
    return {"code": r["code"], "stderr": r["stderr"], "check_seconds": r["wall"], "mode": m.group(1) if m else None,
            "indirect": bool(re.search(r"indirect light: yes", out))}


def render(photon, scene, image, width, height, seconds, threads=2, extra=()):
    """photon's image of `scene` with its defaults at width x height. Returns {code, cpu, wall,
    stderr, image (or None)}."""
    os.makedirs(os.path.dirname(image), exist_ok=True)
    if os.path.exists(image):
        os.remove(image)
    cmd = [photon, "render", os.path.basename(scene), "-o", image, "--width", str(width), "--height", str(height),
           "--threads", str(threads), "--no-stats", "-q"] + scenes.photon_options(scene) + list(extra)
    r = runner.run(cmd, os.path.dirname(scene), seconds)
    r["image"] = image if r["code"] == 0 and os.path.exists(image) else None
    return r


def status(r):
    code = r.get("code")
    if code == 0:
        return "rendered"
    if code is None:
        return "time limit"
    if code < 0:
        return "crashed (signal %d)" % -code
    return "error"
