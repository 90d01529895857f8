#!/usr/bin/env python3
"""Writes a small BIDS derivatives tree for the cohort workflow's test, with the standard library
only (a minimal NIfTI-1 writer: no numpy or nibabel on a bare Debian):
  sub-01/anat/sub-01_dseg.nii.gz        label map, a ball (label 1) and a box (label 2), 1 mm
  sub-02/ses-1/anat/sub-02_ses-1_dseg.nii.gz   label map, an ellipsoid (label 5), 1 x 1 x 2 mm
  sub-03/anat/sub-03_T1w.nii            grayscale (float32): a bright ball with a soft edge
  sub-04/anat/sub-04_dseg.nii.gz        a label map cut off half way (unreadable)
and expected.json: every mesh's voxel volume in mL, which its mesh's volume should be close to.
With --reruns, inputs whose data lie in more than one file, for the rerun test:
  p01/                  a DICOM series folder (8 slices of a ball, label 1; explicit VR little endian)
  p02.nhdr              a detached NRRD header, its voxels in voxels-p02.raw (a box, label 1)
  p03.mhd               a detached MetaImage header, its voxels in voxels-p03.raw (a box, label 1)
Usage: make_cohort.py [--reruns] FOLDER"""
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


def dicom_element(group, element, vr, value):
    """One explicit VR little endian element; value: bytes, str or an int for US/UL."""
    if isinstance(value, int):
        value = struct.pack("<H" if vr == "US" else "<I", value)
    elif isinstance(value, str):
        value = value.encode()
    if len(value) % 2:
        value += b"\0" if vr in ("UI", "OB") else b" "
    if vr in ("OB", "OW", "UN", "SQ", "UT"):
        return struct.pack("<HH2sHI", group, element, vr.encode(), 0, len(value)) + value
    return struct.pack("<HH2sH", group, element, vr.encode(), len(value)) + value


def dicom_slice(k, rows, columns, spacing, thickness, pixels):
    """A CT image storage file of slice k (uint16 pixels, row by row), in a series of its own UIDs."""
    root, ct = "1.2.826.0.1.3680043.2.1143.7", "1.2.840.10008.5.1.4.1.1.2"
    instance = f"{root}.3.{k + 1}"
    meta = (dicom_element(0x0002, 0x0001, "OB", b"\0\1") + dicom_element(0x0002, 0x0002, "UI", ct)
            + dicom_element(0x0002, 0x0003, "UI", instance)
            + dicom_element(0x0002, 0x0010, "UI", "1.2.840.10008.1.2.1")
            + dicom_element(0x0002, 0x0012, "UI", root + ".9"))
    elements = [
        (0x0008, 0x0016, "UI", ct), (0x0008, 0x0018, "UI", instance), (0x0008, 0x0060, "CS", "CT"),
        (0x0010, 0x0010, "PN", "Cohort^Test"), (0x0010, 0x0020, "LO", "p01"),
        (0x0018, 0x0050, "DS", f"{thickness:g}"),
        (0x0020, 0x000D, "UI", root + ".1"), (0x0020, 0x000E, "UI", root + ".2"),
        (0x0020, 0x0011, "IS", "1"), (0x0020, 0x0013, "IS", str(k + 1)),
        (0x0020, 0x0032, "DS", f"0\\0\\{k * thickness:g}"), (0x0020, 0x0037, "DS", "1\\0\\0\\0\\1\\0"),
        (0x0020, 0x0052, "UI", root + ".4"),
        (0x0028, 0x0002, "US", 1), (0x0028, 0x0004, "CS", "MONOCHROME2"),
        (0x0028, 0x0010, "US", rows), (0x0028, 0x0011, "US", columns),
        (0x0028, 0x0030, "DS", f"{spacing:g}\\{spacing:g}"),
        (0x0028, 0x0100, "US", 16), (0x0028, 0x0101, "US", 16), (0x0028, 0x0102, "US", 15),
        (0x0028, 0x0103, "US", 0),
        (0x0028, 0x1052, "DS", "0"), (0x0028, 0x1053, "DS", "1"),
        (0x7FE0, 0x0010, "OW", struct.pack("<%dH" % len(pixels), *pixels)),
    ]
    data = b"".join(dicom_element(*e) for e in elements)
    return b"\0" * 128 + b"DICM" + dicom_element(0x0002, 0x0000, "UL", len(meta)) + meta + data


def detached(root, name, header, voxels):
    os.makedirs(root, exist_ok=True)
    with open(f"{root}/{name}", "w") as out:
        out.write(header)
    with open(f"{root}/voxels-{os.path.splitext(name)[0]}.raw", "wb") as out:
        out.write(bytes(voxels))


def reruns(root):
    size, spacing, thickness, slices = 24, 1.0, 2.0, 8
    for k in range(slices):
        pixels = [1 if (i - 11.5) ** 2 + (j - 11.5) ** 2 + ((k - 3.5) * thickness) ** 2 <= 7.5 ** 2 else 0
                  for j in range(size) for i in range(size)]
        write(f"{root}/p01/IM{k + 1:04d}.dcm", dicom_slice(k, size, size, spacing, thickness, pixels), False)
    box = grid((20, 20, 20), (1, 1, 1), lambda x, y, z: 1 if 5 <= min(x, y, z) and max(x, y, z) <= 14 else 0)
    detached(root, "p02.nhdr", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 20 20 20\n"
             "spacings: 1 1 1\nencoding: raw\ndata file: voxels-p02.raw\n", box)
    detached(root, "p03.mhd", "ObjectType = Image\nNDims = 3\nDimSize = 20 20 20\n"
             "ElementSpacing = 1 1 1\nElementType = MET_UCHAR\nElementDataFile = voxels-p03.raw\n", box)


if __name__ == "__main__":
    if sys.argv[1] == "--reruns":
        reruns(sys.argv[2])
    else:
        main(sys.argv[1])
