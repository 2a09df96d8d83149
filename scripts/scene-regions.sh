# SPDX-License-Identifier: MIT
# Sourced by scripts/compare-povray.sh and scripts/accuracy-study.sh: the surfaces of the example
# scenes whose mean radiance photon-compare reports, in scene coordinates: a thin box around each
# wall's inner face and the direction the face looks (see tools/compare_renders.cpp).
# set_regions SCENE sets the array region_args.
set_regions() {
  case "$1" in
    cornell | recursive | textures | patterns | blobs)  # patterns.pov, textures.pov and blobs.pov are the Cornell box too
      region_args=(--region "floor=-1.2,-0.001,-1.2,1.2,0.001,1.2,+y"
        --region "ceiling=-1.2,1.799,-1.2,1.2,1.801,1.2,-y"
        --region "back wall=-1.2,0,1.199,1.2,1.8,1.201,-z"
        --region "left wall (red)=-1.201,0,-1.2,-1.199,1.8,1.2,+x"
        --region "right wall (blue)=1.199,0,-1.2,1.201,1.8,1.2,-x") ;;
    room1 | room2)
      region_args=(--region "floor=-2,-0.001,-2,2,0.001,2,+y"
        --region "ceiling=-2,2.499,-2,2,2.501,2,-y"
        --region "back wall (window)=-2,0,1.999,2,2.5,2.001,-z"
        --region "left wall=-2.001,0,-2,-1.999,2.5,2,+x") ;;  # the right wall is out of view
    *) echo "set_regions: no wall regions for scene '$1'" >&2; return 1 ;;
  esac
}
