# SPDX-License-Identifier: MIT
"""docs/pov-compatibility.md from one run's results (scripts/pov-corpus.py)."""
import collections
import os
import statistics

from . import notes, photon_runs


def warnings_of(entry):
    return [d for d in photon_runs.diagnostics(entry["check"]["stderr"]) if d[0] == "warning"]


def verdict(entry):
    """alike, differs (warned), differs, or why there is no comparison."""
    pov, pho = entry.get("povray"), entry.get("photon")
    if entry["check"]["code"] != 0:
        return "photon check fails"
    if pov is None:
        return "not rendered"
    if not pov.get("image"):
        return "POV-Ray error" if pov.get("code") is not None else "POV-Ray time limit"
    if not pho or not pho.get("image"):
        return "photon " + (photon_runs.status(pho) if pho else "not rendered")
    if entry["difference"]["alike"]:
        return "alike"
    return "differs, warned" if warnings_of(entry) else "differs"


def row_summary(entry):
    v = verdict(entry)
    cpu = ""
    if entry.get("povray") and entry.get("photon") and entry["povray"].get("image") and entry["photon"].get("image"):
        cpu = " cpu %.2f/%.2f s" % (entry["photon"]["cpu"], entry["povray"]["cpu"])
    d = entry.get("difference")
    return v + cpu + (" (%.1f%% of blocks)" % (100 * d["differing"]) if d else "")


def ratio(entry):
    pov, pho = entry.get("povray") or {}, entry.get("photon") or {}
    if pov.get("image") and pho.get("image") and pov["cpu"] > 0:
        return pho["cpu"] / max(pov["cpu"], 0.01)
    return None


def quartiles(xs):
    xs = sorted(xs)
    if not xs:
        return None
    q = statistics.quantiles(xs, n=4, method="inclusive") if len(xs) > 1 else [xs[0]] * 3
    return q[0], q[1], q[2]


def write(a, run):
    sc = run["scenes"]
    names = sorted(sc)
    n = len(names)
    passed = [s for s in names if sc[s]["check"]["code"] == 0]
    crashed = [s for s in names if sc[s]["check"]["code"] is not None and sc[s]["check"]["code"] < 0]
    clean = [s for s in passed if not warnings_of(sc[s])]
    L = ["# POV-Ray's sample scenes in photon\n"]
    L.append("Written by `scripts/pov-corpus.py` (do not edit by hand) on %s, on %s: every `.pov` file of "
             "Debian's `povray-examples` (POV-Ray 3.7, `%s`) read by `photon check` from its own directory, with the "
             "standard includes of `povray-includes`." % (run["date"], run["machine"], run["examples"]))
    compared = [s for s in names if sc[s].get("povray", {}) and sc[s]["povray"].get("image")]
    if run.get("povray"):
        if run.get("photon_commit"):
            L.append(" photon built from commit %s." % run["photon_commit"])
        L.append(" Each scene rendered at %dx%d by %s (`+A0.3`, the file's own settings, cached between runs) "
                 "and by photon with its defaults (`photon render SCENE --width %d --height %d`: `rt` where the "
                 "file has no radiosity or photons, `pm` where it has), one render at a time, both on %d threads, "
                 "CPU time of the whole command (user + system). Time limits: POV-Ray %g s, photon %g s.\n"
                 % (run["width"], run["height"], run["povray"], run["width"], run["height"], run["threads"],
                    run["povray_seconds"], run["photon_seconds"]))
        L.append("**The measure.** Both 8-bit images are averaged over blocks of 8 x 8 pixels, so that texture "
                 "grain, sampling noise and anti-aliasing average out; a block differs where one of its channels' "
                 "means differs by more than 20/255; a scene is *alike* where at most 3% of its blocks differ "
                 "(`scripts/pov_corpus/compare.py`). *Warned*: photon printed at least one located warning for the "
                 "scene (what it skipped or approximated).\n")
    else:
        L.append(" No render in this run.\n")
    L.append("| | scenes | share |\n|---|---:|---:|")
    row = lambda name, k, of=n: L.append("| %s | %d | %.0f%% |" % (name, k, 100.0 * k / max(of, 1)))
    row("sample scenes", n)
    row("pass `photon check`", len(passed))
    row("pass with no warning", len(clean))
    row("crash (must be 0)", len(crashed))
    if compared:
        m = len(compared)
        v = {s: verdict(sc[s]) for s in compared}
        L.append("| **rendered by POV-Ray** (the shares below are of these) | %d | |" % m)
        row("alike", sum(1 for s in compared if v[s] == "alike"), m)
        row("alike, or different with a warning", sum(1 for s in compared if v[s] in ("alike", "differs, warned")), m)
        row("different without a warning", sum(1 for s in compared if v[s] == "differs"), m)
        row("photon check fails", sum(1 for s in compared if v[s] == "photon check fails"), m)
        row("photon hit its time limit", sum(1 for s in compared if v[s] == "photon time limit"), m)
        rs = {s: ratio(sc[s]) for s in compared if ratio(sc[s]) is not None}
        L.append("")
        L.append("## CPU time against POV-Ray\n")
        L.append("photon's CPU time over POV-Ray's, per scene that both rendered (%d scenes; below 1: photon is "
                 "faster). By photon's mode:\n" % len(rs))
        L.append("| scenes | count | lower quartile | median | upper quartile | scenes over 3x |\n|---|---:|---:|---:|---:|---:|")
        for label, subset in (("all", list(rs)),
                              ("photon `rt`", [s for s in rs if sc[s]["check"].get("mode") == "rt"]),
                              ("photon `pm`", [s for s in rs if sc[s]["check"].get("mode") == "pm"])):
            q = quartiles([rs[s] for s in subset])
            if q:
                L.append("| %s | %d | %.2f | %.2f | %.2f | %d |" % (label, len(subset), q[0], q[1], q[2],
                                                                    sum(1 for s in subset if rs[s] > 3)))
        L.append("")
        L.append("The slowest ten against POV-Ray:\n")
        L.append("| scene | mode | photon CPU s | POV-Ray CPU s | ratio | why |\n|---|---|---:|---:|---:|---|")
        for s in sorted(rs, key=lambda s: -rs[s])[:10]:
            L.append("| %s | %s | %.2f | %.2f | %.1f | %s |" % (s, sc[s]["check"].get("mode"), sc[s]["photon"]["cpu"],
                                                              sc[s]["povray"]["cpu"], rs[s], notes.slow.get(s, "")))
        L.append("")
    write_judged(L, sc, names)
    write_warnings(L, sc, names)
    write_failures(L, sc, names)
    if compared:
        write_sheets(a, L, sc, compared)
    write_every_scene(L, sc, names, bool(compared))
    with open(a.out, "w") as f:
        f.write("\n".join(L) + "\n")


def write_judged(L, sc, names):
    judged = [s for s in names if sc[s].get("judge")]
    if not judged:
        return
    seconds = max(sc[s]["judge"].get("sppm_seconds", 0) for s in judged)
    L.append("## Global illumination: which program is right\n")
    L.append("The scenes photon renders in `pm` (their files ask for radiosity). *Language*: photon `rt` against "
             "POV-Ray at `+Q8` (radiosity, photons and media off), by the corpus measure. *Against the judge*: "
             "the relative RMS difference of linear 8x8 block means from photon's `sppm` (two runs of %d s, seeds 1 "
             "and 2; the judge is their mean, its noise floor half the RMS of their difference), for photon `pm` "
             "with its defaults and POV-Ray with the file's radiosity. *Closer*: the smaller error, where the two "
             "differ by more than the floor. Like photon's `pm`, the judge sees light from light sources and the "
             "sky only: where a file's surfaces glow (`emission`, or `ambient` before 3.7) POV-Ray's radiosity lets "
             "them light others, and photon warns.\n" % seconds)
    L.append("| scene | language (blocks differing) | judge's floor | photon `pm` | POV-Ray | closer | photon CPU s | POV-Ray CPU s |")
    L.append("|---|---:|---:|---:|---:|---|---:|---:|")
    for s in judged:
        j, e = sc[s]["judge"], sc[s]
        lang = j.get("language")
        pe, ve, fl = j.get("photon_error"), j.get("povray_error"), j.get("floor")
        closer = ""
        if pe is not None and ve is not None and fl is not None:
            closer = "neither resolved" if abs(pe - ve) <= fl else ("photon" if pe < ve else "POV-Ray")
        fmt = lambda x: "%.1f%%" % (100 * x) if x is not None else ""
        L.append("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            s, ("%.1f%%%s" % (100 * lang["differing"], "" if lang["alike"] else " (differs)")) if lang else "",
            fmt(fl), fmt(pe), fmt(ve), closer,
            "%.2f" % e["photon"]["cpu"] if (e.get("photon") or {}).get("image") else "",
            "%.2f" % e["povray"]["cpu"] if (e.get("povray") or {}).get("image") else ""))
    L.append("")


def write_warnings(L, sc, names):
    kinds = collections.Counter()
    kind_scenes = collections.defaultdict(set)
    for s in names:
        for _, _, msg in warnings_of(sc[s]):
            k = photon_runs.warning_kind(msg)
            kinds[k] += 1
            kind_scenes[k].add(s)
    L.append("## Warnings by kind\n")
    L.append("What photon skipped or approximated, over all scenes (a warning counted once per place). Notes "
             "(a scene without light sources that shows what POV-Ray shows, the scene's own `#warning`) report no "
             "approximation and are not counted.\n")
    L.append("| warning | times | scenes |\n|---|---:|---:|")
    for k, c in kinds.most_common(40):
        L.append("| %s | %d | %d |" % (k.replace("|", "\\|"), c, len(kind_scenes[k])))
    L.append("")


def write_failures(L, sc, names):
    errors = collections.Counter()
    for s in names:
        if sc[s]["check"]["code"] != 0:
            errors[photon_runs.warning_kind(photon_runs.first_error(sc[s]["check"]["stderr"])[1])] += 1
    L.append("## What stops the scenes that fail\n")
    L.append("| first error | scenes |\n|---|---:|")
    for k, c in errors.most_common(40):
        L.append("| %s | %d |" % (k.replace("|", "\\|"), c))
    L.append("")


def write_sheets(a, L, sc, compared):
    from . import compare
    differ = [s for s in compared if verdict(sc[s]) in ("differs", "differs, warned") or
              (verdict(sc[s]).startswith("photon") and sc[s].get("photon"))]
    os.makedirs(a.sheets, exist_ok=True)
    for f in os.listdir(a.sheets):
        if f.startswith("sheet-"):
            os.remove(os.path.join(a.sheets, f))
    L.append("## The scenes that differ\n")
    L.append("POV-Ray | photon | the block difference (four times brighter; blocks beyond the tolerance outlined "
             "red), %d scenes, in the order of the table below.\n" % len(differ))
    per = 12
    for i in range(0, len(differ), per):
        chunk = differ[i:i + per]
        name = "sheet-%02d.jpg" % (i // per + 1)
        rows = [("%s  (%s)" % (s, verdict(sc[s])), sc[s]["povray"]["image"], (sc[s].get("photon") or {}).get("image"))
                for s in chunk]
        compare.contact_sheet(rows, os.path.join(a.sheets, name))
        rel = os.path.relpath(os.path.join(a.sheets, name), os.path.dirname(a.out))
        L.append("![%s to %s](%s)\n" % (chunk[0], chunk[-1], rel))
    L.append("")


def write_every_scene(L, sc, names, compared):
    L.append("## Every scene\n")
    if compared:
        L.append("| scene | photon check | mode | photon CPU s | POV-Ray CPU s | ratio | blocks differing | verdict | note |")
        L.append("|---|---|---|---:|---:|---:|---:|---|---|")
    else:
        L.append("| scene | check | first error |\n|---|---|---|")
    for s in names:
        e = sc[s]
        c = e["check"]
        ok = c["code"] == 0
        check_text = ("ok, %d warnings" % len(warnings_of(e))) if ok else (
            "time limit" if c["code"] is None else ("crash" if c["code"] < 0 else "error"))
        note = notes.differences.get(s, "")
        if not ok:
            loc, msg = photon_runs.first_error(c["stderr"])
            note = (("`%s` " % loc if loc else "") + msg + ("; " + note if note else ""))
        note = note.replace("|", "\\|")
        if not compared:
            L.append("| %s | %s | %s |" % (s, check_text, note))
            continue
        pov, pho, d = e.get("povray") or {}, e.get("photon") or {}, e.get("difference")
        r = ratio(e)
        L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            s, check_text, c.get("mode") or "", "%.2f" % pho["cpu"] if pho.get("image") else "",
            "%.2f" % pov["cpu"] if pov.get("image") else "", "%.2f" % r if r is not None else "",
            "%.1f%%" % (100 * d["differing"]) if d else "", verdict(e), note))
    L.append("")
