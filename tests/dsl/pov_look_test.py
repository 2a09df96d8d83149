#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""POV-Ray's own sample scenes look in photon as in POV-Ray: a bounded subset of the corpus
comparison (scripts/pov-corpus.py), each scene rendered by both programs at 160x120 now and
compared on 8x8-pixel block means (scripts/pov_corpus/compare.py). The list holds scenes that
stand for what photon reads as POV-Ray does: gamma modes, anti-aliasing, area lights, transparent
shadows, shadowless lights, image maps, polynomial surfaces, an animation's first frame.
Skipped (exit 77) where POV-Ray, its sample scenes, NumPy or Pillow are not installed.

  pov_look_test.py PHOTON LIST SCRIPTS_DIR
"""
import os
import shutil
import sys
import tempfile

SKIP = 77


def main():
    photon, listing, scripts = (os.path.abspath(a) for a in sys.argv[1:4])
    if not shutil.which("povray"):
        print("POV-Ray is not installed: skipping the comparison with POV-Ray's images")
        return SKIP
    try:
        import numpy  # noqa: F401
        import PIL  # noqa: F401
    except ImportError:
        print("NumPy or Pillow is missing (Debian: python3-numpy, python3-pil): skipping")
        return SKIP
    sys.path.insert(0, scripts)
    from pov_corpus import compare, photon_runs, povray, scenes
    examples = scenes.find_examples()
    if not os.path.isdir(examples):
        print("povray-examples is not installed: skipping")
        return SKIP
    names = [l.split("#")[0].strip() for l in open(listing)]
    names = [n for n in names if n]
    failed = []
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            scene = os.path.join(examples, name)
            pov = povray.render(scene, name, os.path.join(work, "povray"), 160, 120, 120, threads=1)
            image = os.path.join(work, "photon", name[:-4] + ".png")
            pho = photon_runs.render(photon, scene, image, 160, 120, 120, threads=1)
            if not pov.get("image"):
                failed.append("%s: POV-Ray did not render it (%s)" % (name, pov.get("stderr_tail", "")[-200:]))
                continue
            if not pho.get("image"):
                failed.append("%s: photon did not render it:\n%s" % (name, pho["stderr"][-600:]))
                continue
            warnings = [d for d in photon_runs.diagnostics(pho["stderr"]) if d[0] == "warning"]
            d = compare.difference(pov["image"], image)
            verdict = "alike" if d["alike"] else "DIFFERS"
            print("%-45s %s: %.1f%% of blocks differ (worst %.3f), %d warnings" %
                  (name, verdict, 100 * d["differing"], d["worst"], len(warnings)))
            if not d["alike"]:
                failed.append("%s: %.1f%% of its 8x8 blocks differ from POV-Ray's image" % (name, 100 * d["differing"]))
            if warnings:
                failed.append("%s: photon warned: %s" % (name, "; ".join(w[2] for w in warnings)))
    for f in failed:
        print("FAIL: " + f)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
