"""The cohort's input volumes, from a BIDS derivatives folder or a glob (see config.yaml).

find_inputs(config) returns {unit: entry}: unit is the results path of the input without
extension ("sub-01/ses-1/sub-01_ses-1_desc-aseg_dseg"); the entry holds path, subject ("sub-01",
or the glob's match), session ("ses-1" or "") and name (the file name without extension).
data_files(path) lists the files SliceMesh reads for one input, which the mesh rule depends on.
"""
import glob
import os
import re

# The extensions of the inputs SliceMesh reads, dropped from an input's name (longest first where
# one ends another): images, segmentation files, structure sets and contour files.
EXTENSIONS = (".seg.nrrd", ".nii.gz", ".nii", ".nrrd", ".nhdr", ".mha", ".mhd", ".dcm", ".json", ".vtp", ".vtk")


class InputError(Exception):
    pass


def header_lines(path, limit=1 << 16):
    """The text lines of a header: a NRRD's up to its blank line, a MetaImage's up to its
    ElementDataFile line's list (a .mha's or .nrrd's voxels follow)."""
    try:
        with open(path, "rb") as f:
            text = f.read(limit)
    except OSError:
        return []
    return text.decode("latin-1").splitlines()


def named_data_files(path):
    """The data files a detached header names (NRRD "data file:", MetaImage "ElementDataFile ="):
    one file, a LIST of files on the lines after it, or a pattern "name%03d.raw first last step";
    relative names lie beside the header. Empty for data in the file itself (LOCAL, attached)."""
    lower = path.lower()
    nrrd, meta = lower.endswith((".nhdr", ".nrrd")), lower.endswith((".mhd", ".mha"))
    if not nrrd and not meta:
        return []
    lines = header_lines(path)
    for at, line in enumerate(lines):
        if nrrd and not line.strip():
            break  # a NRRD's header ends at its first blank line
        if nrrd and line.startswith(("data file:", "datafile:")):
            named = line.split(":", 1)[1].strip()
        elif meta and line.startswith("ElementDataFile") and "=" in line:
            named = line.split("=", 1)[1].strip()
        else:
            continue
        words = named.split()
        if not words or named == "LOCAL":
            return []
        if words[0] == "LIST":
            names = [n.strip() for n in lines[at + 1:] if n.strip()]
        elif "%" in words[0] and len(words) >= 4:
            try:
                first, last, step = int(words[1]), int(words[2]), int(words[3])
                names = [words[0] % i for i in range(first, last + (1 if step > 0 else -1), step)] if step else []
            except (ValueError, TypeError):
                names = [named]
        else:
            names = [named]
        return [os.path.join(os.path.dirname(path), n) for n in names]
    return []


def data_files(path):
    """The files SliceMesh reads for an input: a folder's files (not its subfolders'), a detached
    header and the data files it names, or the file itself. Files that do not exist are left out:
    SliceMesh's run says what is missing, and the other inputs go on."""
    if os.path.isdir(path):
        with os.scandir(path) as entries:
            files = [e.path for e in entries if e.is_file()]  # is_file follows links, as SliceMesh does
    else:
        files = [path] + named_data_files(path)
    return sorted(f for f in dict.fromkeys(files) if os.path.isfile(f))


def strip_extension(name):
    for extension in EXTENSIONS:
        if name.endswith(extension):
            return name[: -len(extension)]
    return name


def entity(path, key):
    """The BIDS entity key-<label> of a path (its last occurrence), or ''."""
    found = re.findall(r"(?:^|[/_])%s-([a-zA-Z0-9]+)" % key, path)
    return found[-1] if found else ""


def bids_paths(root, files):
    if not os.path.isdir(root):
        raise InputError(f"bids_dir '{root}' is not a folder")
    paths = []
    for middle in ("sub-*/anat", "sub-*/ses-*/anat"):
        paths += glob.glob(os.path.join(glob.escape(root), middle, files))
    return paths


def glob_regex(pattern):
    """The glob as a regular expression with one group per wildcard."""
    out, i = "", 0
    while i < len(pattern):
        if pattern.startswith("**/", i):
            out, i = out + "(?:(.*)/)?", i + 3  # any folders, none included
        elif pattern.startswith("**", i):
            out, i = out + "(.*)", i + 2
        elif pattern[i] in "*?":
            out, i = out + ("([^/]*)" if pattern[i] == "*" else "([^/])"), i + 1
        elif pattern[i] == "[" and "]" in pattern[i + 2:]:
            j = pattern.index("]", i + 2)
            out, i = out + "([" + pattern[i + 1 : j].replace("!", "^", 1) + "])", j + 1
        else:
            out, i = out + re.escape(pattern[i]), i + 1
    return out


def glob_id(pattern, path):
    """The folder and file names (extension dropped) in which the glob's wildcards matched,
    joined by "_": "/data/*/labels.nrrd" gives p01 for /data/p01/labels.nrrd, "/data/ct/*" gives
    p01 for /data/ct/p01.nii.gz."""
    match = re.fullmatch(glob_regex(pattern), path)
    spans = [match.span(g) for g in range(1, match.re.groups + 1) if match.group(g)] if match else []
    stem, names, offset = strip_extension(path.rstrip("/")), [], 0
    for name in stem.split("/"):
        if name and any(a < offset + len(name) and b > offset for a, b in spans):
            names.append(name)
        offset += len(name) + 1
    return "_".join(names) or os.path.basename(stem)


def find_inputs(config):
    bids_dir, pattern = config.get("bids_dir") or "", config.get("glob") or ""
    if bool(bids_dir) == bool(pattern):
        raise InputError("set exactly one of bids_dir and glob in the config")
    if bids_dir:
        paths = bids_paths(bids_dir, config.get("bids_files") or "*_dseg.nii*")
    else:
        paths = glob.glob(pattern, recursive=True)
    wanted = {str(p).removeprefix("sub-") for p in config.get("participant_label") or []}

    inputs = {}
    for path in sorted(paths):
        name = strip_extension(os.path.basename(path.rstrip(os.sep)))
        label = entity(path, "sub")
        if wanted and (label or glob_id(pattern, path)) not in wanted:
            continue
        subject = "sub-" + label if label else glob_id(pattern, path)
        session = "ses-" + entity(path, "ses") if entity(path, "ses") else ""
        unit = os.path.join(subject, session, name)
        if unit in inputs:
            raise InputError(f"'{path}' and '{inputs[unit]['path']}' would share the results {unit}.*")
        inputs[unit] = {"path": path, "subject": subject, "session": session, "name": name}
    if not inputs:
        where = f"bids_dir '{bids_dir}'" if bids_dir else f"glob '{pattern}'"
        raise InputError(f"no input found ({where}" + (", participant_label" if wanted else "") + ")")
    return inputs
