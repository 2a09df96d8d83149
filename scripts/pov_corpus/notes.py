# SPDX-License-Identifier: MIT
"""What the report says of particular scenes, from reading them: why a scene differs from
POV-Ray's image on purpose or for a known reason (`differences`), and why it is slow (`slow`).
Keep each note short and true; remove it when the cause is gone."""

differences = {
}

slow = {
}
