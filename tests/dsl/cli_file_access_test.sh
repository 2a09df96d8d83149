#!/bin/sh
# SPDX-License-Identifier: MIT
# Scene files photon did not write, end to end: `photon` refuses what a scene names outside the
# permitted folders (absolute, `..`, a symbolic link), says so with a located error that quotes
# nothing of the refused file, keeps an existing image, and reads the same once the folder is
# permitted (--permit-path, --io-config, --io-restrictions); a PNG declaring 100,000 x 100,000
# pixels and a slow read (--max-parse-seconds) end in clear errors (docs/robustness.md).
#   cli_file_access_test.sh PHOTON WORKDIR
photon=$1 work=$2
rm -rf "$work" && mkdir -p "$work/scene" "$work/outside" "$work/cwd" || exit 1
work=$(cd "$work" && pwd)
cd "$work/cwd" || exit 1  # an empty current folder: it is permitted too
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect() {  # expect STATUS COMMAND...: run and compare the exit status
    want=$1; shift
    "$@" >"$work/out" 2>"$work/err"; got=$?
    [ "$got" -eq "$want" ] || { fail "exit status $got, expected $want: $*"; cat "$work/err"; }
}
has() { grep -qF -- "$1" "$work/err" || { fail "$2: stderr lacks: $1"; cat "$work/err"; }; }
lacks() { grep -qF -- "$1" "$work/err" && { fail "$2: stderr shows: $1"; cat "$work/err"; }; return 0; }

secret=SECRET-c41d-never-printed
printf '%s\n' "$secret" >"$work/outside/secret.inc"
printf 'sphere { 0, 1 }\n' >"$work/outside/ok.inc"
ln -s "$work/outside" "$work/scene/link"
stage='camera { location -5*z look_at 0 } light_source { 5*y, 1 }'
scene() { printf '%s\n%s\n' "$1" "$stage" >"$work/scene/main.pov"; }
printf 'old image' >"$work/old.png"

# /etc/passwd and /etc/hostname, as the issue tried them: refused, nothing of them printed, the
# old image kept.
scene '#include "/etc/passwd"'
expect 1 "$photon" render "$work/scene/main.pov" -o "$work/old.png" --width 8 --height 6
has 'main.pov:1:10: error: reading "/etc/passwd" is not permitted' "/etc/passwd"
has "--permit-path DIR" "/etc/passwd: how to permit it"
lacks "root:" "/etc/passwd"
[ "$(cat "$work/old.png")" = "old image" ] || fail "/etc/passwd: the old image was overwritten"
scene '#fopen F "/etc/hostname" read
#read (F, A)'
expect 1 "$photon" check "$work/scene/main.pov"
has 'main.pov:1:10: error: reading "/etc/hostname" is not permitted' "/etc/hostname"
[ -s /etc/hostname ] && lacks "$(head -c 40 /etc/hostname)" "/etc/hostname"

# `..`, a link to a folder, and writing: each refused at its place.
for name in ../outside/secret.inc link/secret.inc "$work/outside/secret.inc"; do
    scene "#include \"$name\""
    expect 1 "$photon" check "$work/scene/main.pov"
    has "main.pov:1:10: error: reading \"$name\" is not permitted" "include $name"
    lacks "$secret" "include $name"
done
scene 'sphere { 0, 1 pigment { image_map { png "link/x.png" } } }'
expect 1 "$photon" check "$work/scene/main.pov"
has 'main.pov:1:41: error: reading "link/x.png" is not permitted' "image_map through a link"
scene '#fopen F "../outside/out.txt" write'
expect 1 "$photon" check "$work/scene/main.pov"
has 'main.pov:1:10: error: writing "../outside/out.txt" is not permitted' "#fopen write"

# Permitted, the same files are read: the refusals above were the rule's doing.
scene '#include "link/ok.inc"'
expect 0 "$photon" check "$work/scene/main.pov" --permit-path "$work/outside"
scene '#include "../outside/secret.inc"'
expect 1 "$photon" check "$work/scene/main.pov" --permit-path "$work/outside"
has "$secret" "a permitted file's error quotes it"
printf '[File I/O Security]\nrestricted\n[Permitted Paths]\nread* = "%s"\n' "$work/outside" >"$work/povray.conf"
scene '#include "../outside/ok.inc"'
expect 0 "$photon" check "$work/scene/main.pov" --io-config "$work/povray.conf"
expect 0 "$photon" check "$work/scene/main.pov" --io-restrictions read-only
# --io-restrictions overrides the configuration's level.
printf '[File I/O Security]\nnone\n' >"$work/none.conf"
scene '#include "/etc/passwd"'
expect 1 "$photon" check "$work/scene/main.pov" --io-config "$work/none.conf" --io-restrictions restricted
has "under the I/O restrictions \`restricted\` (--io-restrictions)" "--io-restrictions over --io-config"
lacks "root:" "--io-restrictions over --io-config"
printf '[Permitted Paths]\nread+write* /tmp\n' >"$work/bad.conf"
expect 1 "$photon" check "$work/scene/main.pov" --io-config "$work/bad.conf"
has "bad.conf:2:1: error: expected \`=\` and a folder after \`read+write*\`" "bad configuration"
expect 2 "$photon" check "$work/scene/main.pov" --io-restrictions sometimes

# A small PNG that declares 100,000 x 100,000 pixels: refused before its pixels are allocated.
if command -v python3 >/dev/null; then
    python3 - "$work/scene/huge.png" <<'EOF'
import struct, sys, zlib
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"\0" * 1000)) + chunk(b"IEND", b"")
open(sys.argv[1], "wb").write(png)
EOF
    scene 'sphere { 0, 1 pigment { image_map { png "huge.png" } } }'
    expect 1 "$photon" render "$work/scene/main.pov" -o "$work/old.png" --width 8 --height 6
    has "main.pov:1:41: error: cannot read the image:" "huge PNG"
    has "declares 100000 x 100000 pixels" "huge PNG"
    [ "$(cat "$work/old.png")" = "old image" ] || fail "huge PNG: the old image was overwritten"
fi

# A read that takes too long ends in an error where it stopped (its timing is not tested).
scene '#declare I = 0; #while (I < 1e6) #declare I = I + 1; #end'
expect 1 "$photon" check "$work/scene/main.pov" --max-parse-seconds 0.000001
has "error: the scene takes too long to read: more than 1e-06 seconds" "--max-parse-seconds"
expect 2 "$photon" check "$work/scene/main.pov" --max-parse-seconds -1

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "cli_file_access_test: all passed"
