# SPDX-License-Identifier: MIT
"""What the report says of particular scenes, from reading them: why a scene differs from
POV-Ray's image on purpose or for a known reason (`differences`), and why it is slow (`slow`).
Keep each note short and true; remove it when the cause is gone."""

# Why photon's `pm` scenes take longer than POV-Ray's radiosity at 320x240: photon's counts do not
# shrink with the image (200,000 photons, 256-ray gathers, irradiance-cache records bounded by
# the pixels of an 800-pixel-wide image), and its error estimate (a short sppm run) comes with
# every render. POV-Ray's radiosity gathers fewer rays at fewer points, and sees one bounce less.
_PM_FIXED_COST = ("pm's photon counts, gathers and cache density are fixed, not scaled to a small image; "
                  "its error estimate runs with every render")

differences = {
    "language/tracevines.pov": "the vines grow by trace() and rand(): a trace that lands a hair apart sends "
                               "a vine on another random path",
    "advanced/quilt1.pov": "the quilted normal's tiles shade rounder in photon than in POV-Ray; cause not found",
    "animations/raddem/raddem.pov": "on purpose: photon's red bleeds more onto the walls and floor, and its pm is "
                                    "within 2.1% of the sppm judge where POV-Ray's radiosity is 19% off; the "
                                    "language alone (rt against POV-Ray +Q8) is alike",
    "radiosity/cornell.pov": "on purpose: photon's pm is within 1.9% of the sppm judge where POV-Ray's radiosity "
                             "(count 200) is 86% off; the language alone (rt against POV-Ray +Q8) is alike",
}

slow = {
    "objects/quartic/helix.pov": "quartics in CSG: every ray finds all roots of the quartic and its "
                                 "derivatives to full precision (bracketed Newton), and walks the CSG",
    "advanced/pawns.pov": "three quartics in CSG: root finding per ray, as helix",
}
for _scene in ("radiosity/radiosity_36.pov", "radiosity/radiosity_37.pov", "radiosity/radiosity2.pov",
               "animations/raddem/raddem.pov", "radiosity/rad_def_test_37.pov", "radiosity/rad_def_test_36.pov",
               "radiosity/patio-radio_37.pov", "radiosity/patio-radio_36.pov", "advanced/grenadine/grenadine.pov",
               "advanced/object_pattern.pov", "gamma/gamma_showcase.pov", "advanced/blocks/stackerday.pov",
               "radiosity/cornell.pov", "advanced/blocks/stackernight.pov"):
    slow.setdefault(_scene, _PM_FIXED_COST)
