#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Written pictures are not blank.

    checkPictures.py PNG...

Each PNG must exist, and beyond its background (its most common colour)
hold at least 2 % of its pixels in at least 16 distinct colours: a bed of
parcels coloured by a field, not an empty or one-colour frame.
"""
import sys
from collections import Counter

import matplotlib.image as mpimg
import numpy as np


def main():
    ok = True
    for path in sys.argv[1:]:
        try:
            img = mpimg.imread(path)
        except (OSError, ValueError) as e:
            print(f'FAIL: {path}: {e}')
            ok = False
            continue
        rgb = (np.asarray(img)[..., :3] * 255).round().astype(np.uint8)
        pixels = [tuple(p) for p in rgb.reshape(-1, 3)]
        counts = Counter(pixels)
        background, nb = counts.most_common(1)[0]
        fraction = 1 - nb / len(pixels)
        colours = len(counts) - 1
        good = fraction >= 0.02 and colours >= 16
        print(f'{path}: {img.shape[1]}x{img.shape[0]}, background {background},'
              f' {100 * fraction:.1f} % of pixels in {colours} other colours'
              f' {"ok" if good else "BLANK"}')
        ok &= good
    print('PASS' if ok else 'FAIL')
    sys.exit(0 if ok else 1)


main()
