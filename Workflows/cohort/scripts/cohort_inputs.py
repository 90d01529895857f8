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


def glob_id(pattern, path):
    """The part of path that the glob's wildcards matched: below its last wildcard-free folder."""
    fixed = []
    for part in pattern.split(os.sep):
        if glob.has_magic(part):
            break
        fixed.append(part)
    relative = os.path.relpath(path, os.sep.join(fixed) or os.sep)
    return strip_extension(relative).replace(os.sep, "_")


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
