# SPDX-License-Identifier: MIT
"""How two renders of a scene differ, as a viewer sees them, and contact sheets of the ones that do.

The measure: both 8-bit images (sRGB values, as the files hold them) are averaged over blocks of
8 x 8 pixels, so that texture grain, sampling noise and anti-aliasing average out and what is
left is what the eye compares: brightness, colour, shapes, shadows, reflections. A block differs
when one of its channels' means differs by more than BLOCK_TOLERANCE (of full scale); a scene's
images are alike when at most ALIKE_SHARE of its blocks differ. Needs NumPy and Pillow (Debian's
python3-numpy, python3-pil, for /usr/bin/python3)."""
import numpy as np
from PIL import Image, ImageDraw

BLOCK = 8
BLOCK_TOLERANCE = 0.08  # 20 of 255: a step anyone sees side by side
ALIKE_SHARE = 0.03      # 3% of the blocks: a small object, a highlight, a shadow's edge


def load(path):
    """The image as an H x W x 3 array of sRGB values in [0, 1] (alpha dropped, grey made RGB)."""
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"), dtype=np.float64) / 255.0


def block_means(img, block=BLOCK):
    h, w = (img.shape[0] // block) * block, (img.shape[1] // block) * block
    return img[:h, :w].reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))


def difference(a_path, b_path):
    """{blocks, differing (share of blocks beyond the tolerance), worst (largest block difference),
    mean (mean absolute difference of the block means), alike} of two images of the same size."""
    a, b = load(a_path), load(b_path)
    if a.shape != b.shape:
        return {"blocks": 0, "differing": 1.0, "worst": 1.0, "mean": 1.0, "alike": False,
                "size_mismatch": "%s against %s" % (a.shape[:2], b.shape[:2])}
    d = np.abs(block_means(a) - block_means(b)).max(axis=2)
    differing = float((d > BLOCK_TOLERANCE).mean())
    return {"blocks": int(d.size), "differing": differing, "worst": float(d.max()), "mean": float(d.mean()),
            "alike": differing <= ALIKE_SHARE}


def difference_image(a, b):
    """|a - b| of the block means, four times brighter, blocks beyond the tolerance outlined red."""
    d = np.abs(block_means(a) - block_means(b))
    big = np.kron(np.clip(d * 4.0, 0.0, 1.0), np.ones((BLOCK, BLOCK, 1)))
    out = np.zeros_like(a)
    out[:big.shape[0], :big.shape[1]] = big
    over = d.max(axis=2) > BLOCK_TOLERANCE
    for by, bx in zip(*np.nonzero(over)):
        y, x = by * BLOCK, bx * BLOCK
        out[y, x:x + BLOCK] = out[y + BLOCK - 1, x:x + BLOCK] = (1, 0, 0)
        out[y:y + BLOCK, x] = out[y:y + BLOCK, x + BLOCK - 1] = (1, 0, 0)
    return out


def contact_sheet(rows, path, thumb=(160, 120)):
    """One image of rows (label, POV-Ray image path, photon image path or None): POV-Ray | photon |
    the block difference, each scaled to `thumb`, the label above them."""
    label_h = 14
    w, h = thumb
    sheet = Image.new("RGB", (3 * w + 8, len(rows) * (h + label_h + 4)), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    for i, (label, pov, pho) in enumerate(rows):
        y = i * (h + label_h + 4)
        draw.text((2, y + 1), label, fill=(0, 0, 0))
        a = load(pov)
        b = load(pho) if pho else np.zeros_like(a)
        if b.shape != a.shape:
            b = np.zeros_like(a)
        tiles = [a, b, difference_image(a, b)]
        for j, t in enumerate(tiles):
            im = Image.fromarray((t * 255 + 0.5).astype(np.uint8)).resize(thumb, Image.BILINEAR)
            sheet.paste(im, (j * (w + 4), y + label_h))
    sheet.save(path, quality=85)
