# SPDX-License-Identifier: MIT
"""The scenes with global illumination (POV-Ray's radiosity, photon's pm): which of the two
programs is right, and whether photon reads the file as POV-Ray does without it.

- photon `rt` against POV-Ray at +Q8 (radiosity, photons and media off in POV-Ray): the language
  alone, by the corpus measure (compare.py).
- photon `pm` (the corpus render) and POV-Ray with radiosity, each against photon's `sppm`, the
  consistent judge that sees every path: two sppm runs of --judge-seconds each with seeds 1 and 2,
  their mean the judge, half the RMS of their difference its noise floor. The error is the relative RMS
  difference of linear 8x8 block means (the 8-bit files decoded by the sRGB curve), over the mean."""
import os

import numpy as np

from . import compare, photon_runs, povray



def linear_blocks(path):
    v = compare.load(path)
    lin = np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
    return compare.block_means(lin)


def relative_rms(a, b, mean):
    return float(np.sqrt(np.mean((a - b) ** 2)) / max(mean, 1e-9))


def radiosity_rows(a, photon, examples, run, rel):
    q8_cache = povray.cache_folder(a.cache, a.width, a.height, radiosity_off=True)
    for name, entry in sorted(run["scenes"].items()):
        c = entry["check"]
        if c["code"] != 0 or c.get("mode") != "pm" or not c.get("indirect"):
            continue
        if a.only and not entry.get("photon"):
            continue
        if a.resume and "floor" in entry.get("judge", {}):
            continue
        scene = os.path.join(examples, name)
        j = entry["judge"] = {}
        pov_q8 = povray.render(scene, name, q8_cache, a.width, a.height, a.povray_seconds, a.threads, radiosity_off=True)
        rt_image = os.path.join(a.work, "photon-rt", name[:-4] + ".png")
        rt = photon_runs.render(photon, scene, rt_image, a.width, a.height, a.photon_seconds, a.threads, ["--mode", "rt"])
        if pov_q8.get("image") and rt["image"]:
            j["language"] = compare.difference(pov_q8["image"], rt["image"])
        judges = []
        for seed in (1, 2):
            image = os.path.join(a.work, "photon-sppm", "%s-%d.png" % (name[:-4], seed))
            r = photon_runs.render(photon, scene, image, a.width, a.height, a.judge_seconds + 120, a.threads,
                                   ["--mode", "sppm", "--time", str(a.judge_seconds), "--seed", str(seed)])
            if r["image"]:
                judges.append(linear_blocks(r["image"]))
        if len(judges) < 2:
            continue
        judge = (judges[0] + judges[1]) / 2
        mean = float(judge.mean())
        j["floor"] = relative_rms(judges[0], judges[1], mean) / 2
        j["sppm_seconds"] = a.judge_seconds
        if entry.get("photon", {}).get("image"):
            j["photon_error"] = relative_rms(linear_blocks(entry["photon"]["image"]), judge, mean)
        if entry.get("povray", {}).get("image"):
            j["povray_error"] = relative_rms(linear_blocks(entry["povray"]["image"]), judge, mean)
        print("pov-corpus: judge %s: %s" % (name, j), flush=True)
