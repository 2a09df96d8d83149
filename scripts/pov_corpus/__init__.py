# SPDX-License-Identifier: MIT
"""POV-Ray's sample scenes through photon and, where it is installed, through POV-Ray itself.

scenes:   where the sample scenes are, and the first frame of each one's .ini
runner:   running a program with a time limit and measuring its CPU time
povray:   POV-Ray's renders of the scenes, cached between runs
compare:  the block-mean image difference, and contact sheets
report:   docs/pov-compatibility.md

scripts/pov-corpus.py is the command.
"""
