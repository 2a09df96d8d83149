#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""POV-Ray 3.7's sample scenes through photon: which parse, which render, and what stops the rest.

Runs `photon check` on every .pov file of Debian's povray-examples (396 scenes), then renders
each one that passes at 160x120 under a time limit, and writes docs/pov-compatibility.md: the
headline counts, the warnings by kind, the first error of every scene that fails, and the list
of scenes that pass (tests/dsl/pov_corpus_subset.txt, which the test suite re-checks).

  scripts/pov-corpus.py build/photon [--render-seconds 60] [--jobs 2] [--no-render]

Each scene is read from its own directory, as POV-Ray's sample scenes expect; the standard
includes are found where photon finds them (/usr/share/povray-3.7/include). An animation scene
is read as the first frame of its companion .ini file (the one in its directory that names it in
Input_File_Name, else the one with its stem): its frame range, clock range and cyclic flag become
photon's --frames and --clock-range, a Clock= value --clock. Uses only the standard library, so
any python3 runs it.
"""
import argparse
import collections
import concurrent.futures
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DIAGNOSTIC = re.compile(r"^(?P<loc>[^\s:][^:]*:\d+:\d+): (?P<sev>warning|error): (?P<msg>.*)$")


def find_examples():
    """The examples folder of povray-examples, from dpkg when it is installed."""
    try:
        files = subprocess.run(["dpkg", "-L", "povray-examples"], capture_output=True, text=True, check=True)
        povs = [f for f in files.stdout.split("\n") if f.endswith(".pov")]
        if povs:
            return os.path.commonpath(povs)
    except (OSError, subprocess.CalledProcessError):
        pass
    return "/usr/share/doc/povray/examples"


def run(cmd, cwd, seconds):
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace", timeout=seconds)
        return p.returncode, p.stderr, time.monotonic() - start
    except subprocess.TimeoutExpired as e:
        err = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
        return None, err, time.monotonic() - start


def diagnostics(stderr):
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


def read_ini(path):
    """POV-Ray's animation options of an .ini file: {option: value} for the keys photon takes."""
    keys = {"initial_frame": "KFI", "final_frame": "KFF", "initial_clock": "KI", "final_clock": "KF",
            "clock": "K", "cyclic_animation": "KC", "input_file_name": "input"}
    out = {}
    for line in open(path, errors="replace"):
        line = line.split(";", 1)[0].strip()
        if "=" in line:
            key, value = (x.strip() for x in line.split("=", 1))
            if key.lower() in keys and value:
                out[keys[key.lower()]] = value
        for switch in line.split():  # +KFF10, +KI0, +KC, ... (longest prefix first)
            m = re.match(r"^[+-](KFI|KFF|KC|KI|KF|K)(.*)$", switch, re.I)
            if m:
                opt = m.group(1).upper()
                out[opt] = ("on" if switch[0] == "+" else "off") if opt == "KC" else m.group(2)
    return out


def companion_ini(scene):
    """The .ini file that renders `scene`: the one naming it in Input_File_Name, else its stem's."""
    folder, name = os.path.split(scene)
    inis = sorted(f for f in os.listdir(folder) if f.lower().endswith(".ini"))
    for f in inis:
        if read_ini(os.path.join(folder, f)).get("input", "").lower() == name.lower():
            return os.path.join(folder, f)
    stem = os.path.splitext(name)[0].lower()
    same = [f for f in inis if os.path.splitext(f)[0].lower() == stem]
    return os.path.join(folder, same[0]) if same else None


def animation_options(scene):
    """photon's options for the first frame of the scene's companion .ini (none without one)."""
    ini = companion_ini(scene)
    if not ini:
        return []
    o = read_ini(ini)
    try:
        if "KFF" in o:
            first, last = int(o.get("KFI", "1")), int(o["KFF"])
            if o.get("KC", "off").lower() in ("on", "true", "yes", "1"):
                last += 1  # POV-Ray's cyclic animation: one more frame, which it does not render
            return ["--frames", "%d:%d" % (first, last),
                    "--clock-range", "%s:%s" % (float(o.get("KI", "0")), float(o.get("KF", "1")))]
        if "K" in o:
            return ["--clock", str(float(o["K"]))]
    except ValueError:  # an unfilled template (portfolio/__empty.ini)
        pass
    return []


def check(photon, scene):
    code, err, secs = run([photon, "check", os.path.basename(scene)] + animation_options(scene),
                          os.path.dirname(scene), 120)
    return {"code": code, "stderr": err, "check_seconds": secs}


def render(photon, scene, out_dir, seconds):
    name = os.path.splitext(os.path.basename(scene))[0]
    image = os.path.join(out_dir, name + ".png")
    cmd = [photon, "render", os.path.basename(scene), "-o", image, "--width", "160", "--height", "120",
           "--threads", "1", "--no-stats", "-q"] + animation_options(scene)
    code, err, secs = run(cmd, os.path.dirname(scene), seconds)
    return {"render_code": code, "render_stderr": err, "render_seconds": secs}


def render_status(r):
    code = r.get("render_code")
    if code == 0:
        return "rendered"
    if code is None:
        return "time limit"
    if code < 0:
        return "crashed (signal %d)" % -code
    return "error"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("photon")
    ap.add_argument("--examples", default=None)
    ap.add_argument("--render-seconds", type=float, default=60)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--no-render", action="store_true")
    ap.add_argument("--render-every", type=int, default=1,
                    help="render every K-th scene that passes check (a systematic sample when time is short)")
    ap.add_argument("--work", default="/tmp/photon-pov-corpus")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "pov-compatibility.md"))
    ap.add_argument("--subset", default=os.path.join(ROOT, "tests", "dsl", "pov_corpus_subset.txt"))
    a = ap.parse_args()
    photon = os.path.abspath(a.photon)
    examples = a.examples or find_examples()
    scenes = sorted(os.path.join(d, f) for d, _, fs in os.walk(examples) for f in fs if f.endswith(".pov"))
    if not scenes:
        sys.exit("pov-corpus: no .pov files under %s (install povray-examples)" % examples)
    os.makedirs(a.work, exist_ok=True)
    results = {}
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for scene, r in zip(scenes, pool.map(lambda s: check(photon, s), scenes)):
            results[scene] = r
        passed = [s for s in scenes if results[s]["code"] == 0]
        print("pov-corpus: %d of %d scenes pass photon check" % (len(passed), len(scenes)), file=sys.stderr)
        if not a.no_render:
            sample = passed[::max(1, a.render_every)]
            for scene, r in zip(sample, pool.map(lambda s: render(photon, s, a.work, a.render_seconds), sample)):
                results[scene].update(r)
    write_report(a, examples, scenes, results)
    write_subset(a.subset, examples, [s for s in scenes if results[s]["code"] == 0])


def write_subset(path, examples, passed):
    """The scenes that pass, each with the animation options it was checked with."""
    with open(path, "w") as f:
        f.write("# POV-Ray 3.7 sample scenes that pass photon check (written by scripts/pov-corpus.py), each\n"
                "# with the options of its .ini's first frame; tests/dsl/pov_corpus_test.sh checks that they still do.\n")
        f.writelines(" ".join([os.path.relpath(s, examples)] + animation_options(s)) + "\n" for s in passed)


def write_report(a, examples, scenes, results):
    n = len(scenes)
    passed = [s for s in scenes if results[s]["code"] == 0]
    crashed = [s for s in scenes if results[s]["code"] is not None and results[s]["code"] < 0]
    tried = [s for s in passed if "render_code" in results[s]]
    rendered = [s for s in tried if render_status(results[s]) == "rendered"]
    timed = [s for s in tried if render_status(results[s]) == "time limit"]
    clean = [s for s in passed if not diagnostics(results[s]["stderr"])]
    kinds = collections.Counter()
    kind_scenes = collections.defaultdict(set)
    for s in scenes:
        for sev, _, msg in diagnostics(results[s]["stderr"]):
            if sev == "warning":
                k = warning_kind(msg)
                kinds[k] += 1
                kind_scenes[k].add(s)
    errors = collections.Counter()
    for s in scenes:
        if results[s]["code"] != 0:
            errors[warning_kind(first_error(results[s]["stderr"])[1])] += 1
    rel = lambda s: os.path.relpath(s, examples)
    L = []
    L.append("# POV-Ray's sample scenes in photon\n")
    L.append("Written by `scripts/pov-corpus.py` (do not edit by hand): every `.pov` file of Debian's "
             "`povray-examples` (POV-Ray 3.7, `%s`) read by `photon check` from its own directory, with "
             "the standard includes of `povray-includes`; %s\n" % (examples,
             "no render in this run (`--no-render`)." if a.no_render else
             "each scene that passes rendered at 160x120 (`photon render`, default mode, one thread, %g s limit)."
             % a.render_seconds))
    L.append("| | scenes | share |\n|---|---:|---:|")
    row = lambda name, k, of=n: L.append("| %s | %d | %.0f%% |" % (name, k, 100.0 * k / of))
    row("sample scenes", n)
    row("pass `photon check`", len(passed))
    row("pass with no warning", len(clean))
    if not a.no_render:
        if len(tried) < len(passed):
            L.append("| rendered: every %d-th scene that passes, %d scenes | %d | |" % (a.render_every, len(tried), len(tried)))
        # shares of the scenes rendered, not of all: a sample's count says nothing of the rest
        row("render at 160x120 (share of those rendered)", len(rendered), max(len(tried), 1))
        row("hit the render time limit (share of those rendered)", len(timed), max(len(tried), 1))
    row("crash (must be 0)", len(crashed))
    L.append("")
    L.append("## Warnings by kind\n")
    L.append("What photon skipped or approximated, over all scenes (a warning counted once per place). Notes "
             "(a scene without light sources that shows what POV-Ray shows, the scene's own `#warning`) report no "
             "approximation and are not counted.\n")
    L.append("| warning | times | scenes |\n|---|---:|---:|")
    for k, c in kinds.most_common(40):
        L.append("| %s | %d | %d |" % (k.replace("|", "\\|"), c, len(kind_scenes[k])))
    L.append("")
    L.append("## What stops the scenes that fail\n")
    L.append("| first error | scenes |\n|---|---:|")
    for k, c in errors.most_common(40):
        L.append("| %s | %d |" % (k.replace("|", "\\|"), c))
    L.append("")
    L.append("## Every scene\n")
    L.append("| scene | check | render | first error |\n|---|---|---|---|")
    for s in scenes:
        r = results[s]
        ok = r["code"] == 0
        check_text = ("ok, %d warnings" % len(diagnostics(r["stderr"]))) if ok else (
            "time limit" if r["code"] is None else ("crash" if r["code"] < 0 else "error"))
        render_text = "" if not ok or "render_code" not in r else "%s (%.0f s)" % (render_status(r), r["render_seconds"])
        err = ""
        if not ok:
            loc, msg = first_error(r["stderr"])
            err = ("`%s` " % loc if loc else "") + msg
        elif "render_code" in r and render_status(r) == "error":
            loc, msg = first_error(r.get("render_stderr", ""))
            err = "render: " + msg
        L.append("| %s | %s | %s | %s |" % (rel(s), check_text, render_text, err.replace("|", "\\|")))
    with open(a.out, "w") as f:
        f.write("\n".join(L) + "\n")


if __name__ == "__main__":
    main()
