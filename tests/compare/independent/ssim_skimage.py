#!/usr/bin/env python3
"""SSIM by scikit-image, the independent implementation tests/compare/ssim_test.cpp holds ours to.

  ssim_skimage.py ACTUAL.png EXPECTED.png [MASK.png]

prints two numbers: the mean SSIM as structural_similarity(gaussian_weights=True, sigma=1.5,
use_sample_covariance=False, data_range=255) gives it on the images' luma (Y = 0.299 R + 0.587 G + 0.114 B of
the stored 8-bit colour, as ours), and the mean of its full map over every pixel (the border included, where
the window is reflected). With MASK (black: left out) the first is over the cropped map's non-black pixels.
Debian's python3-skimage and python3-pil. File names are data: they are only opened.
"""
import sys

import numpy as np
from PIL import Image
from skimage.metrics import structural_similarity


def luma(path):
    rgb = np.asarray(Image.open(path).convert('RGB'), dtype=np.float64)
    return 0.299 * rgb[..., 0] + 0.587 * rgb[..., 1] + 0.114 * rgb[..., 2]


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    a, b = luma(sys.argv[1]), luma(sys.argv[2])
    mean, full = structural_similarity(a, b, gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
                                       data_range=255, full=True)
    if len(sys.argv) == 4:
        pad = 5  # (win_size - 1) // 2, the margin scikit-image crops
        counted = np.asarray(Image.open(sys.argv[3]).convert('RGB')).max(axis=2) > 0
        mean = full[pad:-pad, pad:-pad][counted[pad:-pad, pad:-pad]].mean()
    print(repr(float(mean)), repr(float(full.mean())))


if __name__ == '__main__':
    main()
