# SPDX-License-Identifier: MIT
"""The sample scenes of Debian's povray-examples, and the first frame of each one's .ini file."""
import os
import re
import subprocess


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


def list_scenes(examples):
    return sorted(os.path.join(d, f) for d, _, fs in os.walk(examples) for f in fs if f.endswith(".pov"))


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


def first_frame(scene):
    """The first frame of the scene's companion .ini: ("frames", first, last, clock_from, clock_to,
    cyclic), ("clock", value), or None (no .ini, or one without animation)."""
    ini = companion_ini(scene)
    if not ini:
        return None
    o = read_ini(ini)
    try:
        if "KFF" in o:
            cyclic = o.get("KC", "off").lower() in ("on", "true", "yes", "1")
            return ("frames", int(o.get("KFI", "1")), int(o["KFF"]), float(o.get("KI", "0")),
                    float(o.get("KF", "1")), cyclic)
        if "K" in o:
            return ("clock", float(o["K"]))
    except ValueError:  # an unfilled template (portfolio/__empty.ini)
        pass
    return None


def photon_options(scene):
    """photon's options for the first frame of the scene's companion .ini (none without one)."""
    f = first_frame(scene)
    if f is None:
        return []
    if f[0] == "clock":
        return ["--clock", str(f[1])]
    _, first, last, ki, kf, cyclic = f
    if cyclic:
        last += 1  # POV-Ray's cyclic animation: one more frame, which it does not render
    return ["--frames", "%d:%d" % (first, last), "--clock-range", "%s:%s" % (ki, kf)]


def povray_options(scene):
    """POV-Ray's options for the same frame: the .ini's animation, rendering its first frame only."""
    f = first_frame(scene)
    if f is None:
        return []
    if f[0] == "clock":
        return ["+K%s" % f[1]]
    _, first, last, ki, kf, cyclic = f
    return ["+KFI%d" % first, "+KFF%d" % last, "+KI%s" % ki, "+KF%s" % kf, "+SF%d" % first, "+EF%d" % first] + (
        ["+KC"] if cyclic else [])
