# SPDX-License-Identifier: MIT
# Sourced by the scripts that write their results into the docs (accuracy-study.sh,
# compare-povray.sh, scene-classes.sh): one copy of the marked-block replacement.
# replace_doc_block DOC NAME TEXT replaces the lines from "<!-- NAME: begin" to "<!-- NAME: end"
# in DOC by TEXT (which holds both markers), or appends TEXT when DOC has no such block.
replace_doc_block() {
  local doc=$1 name=$2 text=$3
  if [ -f "$doc" ] && grep -q "^<!-- $name: begin" "$doc"; then
    awk -v block="$text" -v begin="^<!-- $name: begin" -v end="^<!-- $name: end" '
      $0 ~ begin { print block; skip = 1; next }
      $0 ~ end { skip = 0; next }
      !skip { print }' "$doc" >"$doc.tmp"
    mv "$doc.tmp" "$doc"
  else
    printf '%s\n' "$text" >>"$doc"
  fi
}
