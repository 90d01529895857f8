"""The cohort's input volumes, from a BIDS derivatives folder or a glob (see config.yaml).

find_inputs(config) returns {unit: entry}: unit is the results path of the input without
extension ("sub-01/ses-1/sub-01_ses-1_desc-aseg_dseg"); the entry holds path, subject ("sub-01",
or the glob's match), session ("ses-1" or "") and name (the file name without extension).
"""
import glob
import os
import re

EXTENSIONS = (".nii.gz", ".nii", ".nrrd", ".nhdr", ".mha", ".mhd")


class InputError(Exception):
    pass


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
