#!/usr/bin/env python3
"""Writes a small BIDS derivatives tree for the cohort workflow's test, with the standard library
only (a minimal NIfTI-1 writer: no numpy or nibabel on a bare Debian):
  sub-01/anat/sub-01_dseg.nii.gz        label map, a ball (label 1) and a box (label 2), 1 mm
  sub-02/ses-1/anat/sub-02_ses-1_dseg.nii.gz   label map, an ellipsoid (label 5), 1 x 1 x 2 mm
  sub-03/anat/sub-03_T1w.nii            grayscale (float32): a bright ball with a soft edge
  sub-04/anat/sub-04_dseg.nii.gz        a label map cut off half way (unreadable)
and expected.json: every mesh's voxel volume in mL, which its mesh's volume should be close to.
Usage: make_cohort.py FOLDER"""
import gzip
import json
import math
import os
import struct
import sys


def nifti(shape, spacing, datatype, voxels):
    """NIfTI-1 single file: 348-byte header, 4 bytes of no extension, the voxels (x fastest)."""
    bitpix, code = {"uint8": (8, 2), "float32": (32, 16)}[datatype]
    header = bytearray(348)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, 3, *shape, 1, 1, 1, 1)
    struct.pack_into("<hh", header, 70, code, bitpix)
    struct.pack_into("<8f", header, 76, 1.0, *spacing, 0, 0, 0, 0)  # pixdim[0] = qfac
    struct.pack_into("<f", header, 108, 352.0)  # vox_offset
    struct.pack_into("<f", header, 112, 1.0)  # scl_slope
    struct.pack_into("<B", header, 123, 2)  # xyzt_units: mm
    struct.pack_into("<hh", header, 252, 1, 0)  # qform_code scanner, no sform
    struct.pack_into("<6f", header, 256, 0, 0, 0, 0, 0, 0)  # identity rotation, origin 0
    header[344:348] = b"n+1\0"
    pack = "<%d%s" % (len(voxels), "B" if datatype == "uint8" else "f")
    return bytes(header) + b"\0\0\0\0" + struct.pack(pack, *voxels)


def grid(shape, spacing, value):
    """Voxel values from value(x, y, z) at voxel centres in mm, x fastest."""
    nx, ny, nz = shape
    return [value(i * spacing[0], j * spacing[1], k * spacing[2])
            for k in range(nz) for j in range(ny) for i in range(nx)]


def write(path, data, compress):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as out:
        out.write(gzip.compress(data, mtime=0) if compress else data)


def main(root):
    expected = {}

    shape, spacing = (32, 28, 24), (1.0, 1.0, 1.0)
    def two(x, y, z):
        if (x - 10) ** 2 + (y - 13) ** 2 + (z - 11) ** 2 <= 7 ** 2:
            return 1
        return 2 if 19 <= x <= 28 and 6 <= y <= 21 and 5 <= z <= 17 else 0
    voxels = grid(shape, spacing, two)
    write(f"{root}/sub-01/anat/sub-01_dseg.nii.gz", nifti(shape, spacing, "uint8", voxels), True)
    expected["sub-01/1"] = voxels.count(1) / 1000.0
    expected["sub-01/2"] = voxels.count(2) / 1000.0

    shape, spacing = (30, 26, 16), (1.0, 1.0, 2.0)
    def ellipsoid(x, y, z):
        return 5 if ((x - 15) / 11) ** 2 + ((y - 13) / 8) ** 2 + ((z - 15) / 10) ** 2 <= 1 else 0
    voxels = grid(shape, spacing, ellipsoid)
    write(f"{root}/sub-02/ses-1/anat/sub-02_ses-1_dseg.nii.gz", nifti(shape, spacing, "uint8", voxels), True)
    expected["sub-02/5"] = voxels.count(5) * 2.0 / 1000.0

    shape, spacing = (28, 28, 24), (1.0, 1.0, 1.0)
    def bright_ball(x, y, z):  # 800 inside, 100 outside, a 2 mm ramp around radius 8
        r = math.sqrt((x - 14) ** 2 + (y - 14) ** 2 + (z - 12) ** 2)
        return 100.0 + 700.0 * min(1.0, max(0.0, (9.0 - r) / 2.0))
    voxels = grid(shape, spacing, bright_ball)
    write(f"{root}/sub-03/anat/sub-03_T1w.nii", nifti(shape, spacing, "float32", voxels), False)
    expected["sub-03/all"] = sum(v > 450.0 for v in voxels) / 1000.0

    data = gzip.compress(nifti(shape, spacing, "uint8", [1] * (28 * 28 * 24)), mtime=0)
    write(f"{root}/sub-04/anat/sub-04_dseg.nii.gz", data[: len(data) // 2], False)

    with open(f"{root}/expected.json", "w") as out:
        json.dump(expected, out, indent=2)


if __name__ == "__main__":
    main(sys.argv[1])
