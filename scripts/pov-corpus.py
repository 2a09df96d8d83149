#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""POV-Ray 3.7's sample scenes through photon and, where POV-Ray is installed, POV-Ray itself.

Runs `photon check` on every .pov file of Debian's povray-examples (396 scenes), then renders
each scene with POV-Ray (cached between runs) and with photon at the same size on the same
machine, one render at a time, both on 2 threads: POV-Ray with +A0.3 and the file's own
settings, photon with its defaults (which choose rt for a file without radiosity or photons, pm
for one with). It compares the images on 8x8-pixel block means (scripts/pov_corpus/compare.py),
measures the CPU time of each whole command, and writes docs/pov-compatibility.md: the counts,
the CPU-time ratios, the warnings by kind, what stops the scenes that fail, every scene's row,
and contact sheets of the scenes that differ (docs/images/pov-corpus/). It also writes the list
of scenes that pass check (tests/dsl/pov_corpus_subset.txt, which the test suite re-checks).

  scripts/pov-corpus.py build/photon                  # the whole comparison (hours: POV-Ray's cache first)
  scripts/pov-corpus.py build/photon --no-render      # check only (any python3)
  scripts/pov-corpus.py build/photon --only 'camera/*' --report-only ...

Each scene is read from its own directory, as POV-Ray's sample scenes expect, in a copy of the
examples (--work) so that scenes which write files write them there. An animation scene is read
as the first frame of its companion .ini file. The renders need NumPy and Pillow (Debian's
python3-numpy and python3-pil for /usr/bin/python3).
"""
import argparse
import concurrent.futures
import datetime
import fnmatch
import json
import os
import platform
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pov_corpus import photon_runs, povray, report, scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def machine():
    cpu = ""
    try:
        for line in subprocess.run(["lscpu"], capture_output=True, text=True).stdout.split("\n"):
            if line.startswith("Model name:"):
                cpu = line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "%s, %d cores, %s" % (cpu or platform.processor(), os.cpu_count() or 0, platform.platform(terse=True))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("photon")
    ap.add_argument("--examples", default=None)
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--height", type=int, default=240)
    ap.add_argument("--threads", type=int, default=2, help="threads of each render (both programs)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="checks at a time (renders run one at a time)")
    ap.add_argument("--photon-seconds", type=float, default=300, help="photon's time limit per render")
    ap.add_argument("--povray-seconds", type=float, default=600, help="POV-Ray's time limit per render")
    ap.add_argument("--no-render", action="store_true", help="check only")
    ap.add_argument("--no-povray", action="store_true", help="render with photon only")
    ap.add_argument("--only", action="append", default=[], help="render only scenes matching this glob (repeatable)")
    ap.add_argument("--report-only", action="store_true", help="rewrite the report from the last run's results")
    ap.add_argument("--resume", action="store_true",
                    help="keep the renders of the last run (saved after every scene) and render only the rest")
    ap.add_argument("--judge", action="store_true",
                    help="also the radiosity scenes against photon's sppm judge, and POV-Ray at +Q8 against photon rt")
    ap.add_argument("--photon-commit", default=None, help="the commit the photon program was built from, for the report")
    ap.add_argument("--judge-seconds", type=float, default=120,
                    help="time of each of the two sppm judge renders per radiosity scene")
    ap.add_argument("--work", default="/tmp/photon-pov-corpus")
    ap.add_argument("--cache", default=os.path.join(os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")),
                                                    "photon", "pov-corpus"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "pov-compatibility.md"))
    ap.add_argument("--sheets", default=os.path.join(ROOT, "docs", "images", "pov-corpus"))
    ap.add_argument("--subset", default=os.path.join(ROOT, "tests", "dsl", "pov_corpus_subset.txt"))
    a = ap.parse_args()
    results_file = os.path.join(a.work, "results.json")
    if a.report_only:
        with open(results_file) as f:
            run = json.load(f)
        if a.photon_commit:
            run["photon_commit"] = a.photon_commit
        report.write(a, run)
        return
    photon = os.path.abspath(a.photon)
    source = a.examples or scenes.find_examples()
    if not scenes.list_scenes(source):
        sys.exit("pov-corpus: no .pov files under %s (install povray-examples)" % source)
    # A copy: scenes that write files (#fopen ... write) write them beside the copy.
    examples = os.path.join(a.work, "examples")
    if not os.path.isdir(examples):
        shutil.copytree(source, examples)
    all_scenes = scenes.list_scenes(examples)
    rel = lambda s: os.path.relpath(s, examples)
    run = {"date": datetime.date.today().isoformat(), "machine": machine(), "examples": source,
           "width": a.width, "height": a.height, "threads": a.threads, "rendered": not a.no_render,
           "povray": None, "photon_seconds": a.photon_seconds, "povray_seconds": a.povray_seconds,
           "photon_commit": a.photon_commit,
           "scenes": {}}
    previous = {}
    if a.resume and os.path.exists(results_file):
        with open(results_file) as f:
            previous = json.load(f)["scenes"]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for s, r in zip(all_scenes, pool.map(lambda s: photon_runs.check(photon, s), all_scenes)):
            run["scenes"][rel(s)] = {"check": r}
    passed = [s for s in all_scenes if run["scenes"][rel(s)]["check"]["code"] == 0]
    print("pov-corpus: %d of %d scenes pass photon check" % (len(passed), len(all_scenes)), file=sys.stderr)
    if not a.no_render:
        chosen = [s for s in all_scenes if not a.only or any(fnmatch.fnmatch(rel(s), g) for g in a.only)]
        version = None if a.no_povray else povray.version()
        run["povray"] = version
        cache = povray.cache_folder(a.cache, a.width, a.height)
        for i, s in enumerate(chosen):
            entry = run["scenes"][rel(s)]
            if "photon" in previous.get(rel(s), {}) or "povray" in previous.get(rel(s), {}):
                run["scenes"][rel(s)] = previous[rel(s)]
                continue
            if version:
                entry["povray"] = povray.render(s, rel(s), cache, a.width, a.height, a.povray_seconds, a.threads)
            if entry["check"]["code"] == 0:
                image = os.path.join(a.work, "photon", rel(s)[:-4] + ".png")
                r = photon_runs.render(photon, s, image, a.width, a.height, a.photon_seconds, a.threads)
                entry["photon"] = {k: r[k] for k in ("code", "cpu", "wall", "image")}
                entry["photon"]["stderr_tail"] = "\n".join(r["stderr"].strip().split("\n")[-5:])
            if version and entry.get("photon", {}).get("image") and entry["povray"].get("image"):
                from pov_corpus import compare
                entry["difference"] = compare.difference(entry["povray"]["image"], entry["photon"]["image"])
            print("pov-corpus: [%d/%d] %s %s" % (i + 1, len(chosen), rel(s), report.row_summary(entry)),
                  file=sys.stderr, flush=True)
            save(results_file, run)  # a stopped run resumes from here (--resume)
        if a.judge and version:
            from pov_corpus import judge
            judge.radiosity_rows(a, photon, examples, run, rel)
    save(results_file, run)
    report.write(a, run)
    write_subset(a.subset, examples, run)


def save(path, run):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path + ".new", "w") as f:
        json.dump(run, f, indent=1)
    os.replace(path + ".new", path)


def write_subset(path, examples, run):
    """The scenes that pass, each with the animation options it was checked with."""
    with open(path, "w") as f:
        f.write("# POV-Ray 3.7 sample scenes that pass photon check (written by scripts/pov-corpus.py), each\n"
                "# with the options of its .ini's first frame; tests/dsl/pov_corpus_test.sh checks that they still do.\n")
        for name in sorted(run["scenes"]):
            if run["scenes"][name]["check"]["code"] == 0:
                f.write(" ".join([name] + scenes.photon_options(os.path.join(examples, name))) + "\n")


if __name__ == "__main__":
    main()
