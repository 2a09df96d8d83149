#!/usr/bin/env bash
# The contact of docs/design.md ('Near gather hits are traced on'): a red diffuse ball on a white
# floor under a small sphere light. Renders the path tracer (--spp 512 at 160x120, 1024 at
# 320x240), sppm (512 passes of 100,000 photons) and pm with its defaults at seeds 1, 2 and 3, and
# prints, per pm render, how much brighter than each judge it is on the ball's lowest rows (the
# middle half of its width) and on the floor's rows just below them (channel sums).
# Usage: scripts/contact-study.sh [PHOTON_BINARY] (default build/photon); needs
# `scripts/install-deps.sh compare` (NumPy and OpenImageIO's bindings for /usr/bin/python3).
set -euo pipefail
cd "$(dirname "$0")/.."
photon=${1:-build/photon}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/redball.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 10 }
#declare I = 40 / (4*pi);  // a 40 W sphere light of radius 0.05 (units as examples/scenes/cornell.pov)
#declare Fade_D = 0.001;
camera { location <0, 0.6, -1.6> look_at <0, 0.2, 0> up y right x*4/3 angle 75.18 }
light_source { <0.9, 1.6, -0.6>, rgb I / (2*pi*Fade_D*Fade_D)
  area_light <0.1, 0, 0>, <0, 0, 0.1>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2 }
box { <-3, -0.1, -3>, <3, 0, 3> texture { pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } } }
sphere { <0, 0.4, 0>, 0.4 texture { pigment { rgb <0.8, 0.1, 0.1> } finish { ambient 0 diffuse 1 } } }
POV
for size in 160x120 320x240; do
  w=${size%x*} h=${size#*x} spp=$([ "$w" = 160 ] && echo 512 || echo 1024)
  "$photon" render "$work/redball.pov" --width "$w" --height "$h" --mode reference --spp "$spp" -o "$work/ref-$size.exr" -q --no-stats
  "$photon" render "$work/redball.pov" --width "$w" --height "$h" --mode sppm --passes 512 --photons-per-pass 100000 \
    -o "$work/sppm-$size.exr" -q --no-stats
  for seed in 1 2 3; do
    "$photon" render "$work/redball.pov" --width "$w" --height "$h" --mode pm --seed "$seed" -o "$work/pm-$size-$seed.exr" -q --no-stats
  done
  /usr/bin/python3 - "$work" "$size" <<'PY'
import sys, numpy as np, OpenImageIO as oiio
work, size = sys.argv[1], sys.argv[2]
load = lambda p: oiio.ImageBuf(f"{work}/{p}.exr").get_pixels(oiio.FLOAT)[..., :3].astype(np.float64)
ref = load(f"ref-{size}")
H, W, _ = ref.shape
ball = ref[..., 0] > 3 * ref[..., 1] + 1e-6
cols = [x for x in range(W) if ball[:, x].any()]
cols = cols[len(cols) // 4: 3 * len(cols) // 4]
rows = max(1, H // 40)
bands = {}
for name, (a, b) in {"ball's lowest rows": (-rows, 0), "floor below": (2, 2 + rows)}.items():
    m = np.zeros((H, W), bool)
    for x in cols:
        y = np.nonzero(ball[:, x])[0].max()
        m[y + a: y + b, x] = True
    bands[name] = m
for judge in (f"ref-{size}", f"sppm-{size}"):
    J = load(judge)
    for name, m in bands.items():
        ratios = ", ".join(f"{load(f'pm-{size}-{s}')[m].sum() / J[m].sum() - 1:+.1%}" for s in (1, 2, 3))
        print(f"{size} {name} ({m.sum()} px) against {judge.split('-')[0]}: pm seeds 1-3 {ratios}")
PY
done
