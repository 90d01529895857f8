"""The config's SliceMesh options as a command line: passed through, checked only against the
option names `SliceMesh --help` prints, so a new SliceMesh option needs no change here."""
import fnmatch
import re
import subprocess

# Files are the workflow's to name, one set per input.
RESERVED = {"inputVolume", "outputModel", "report", "snapshot", "outputDirectory", "returnparameterfile"}


class OptionError(Exception):
    pass


def help_text(executable):
    try:
        done = subprocess.run([executable, "--help"], capture_output=True, text=True, timeout=60)
    except OSError as error:
        raise OptionError(f"cannot run SliceMesh '{executable}' (config key slicemesh): {error.strerror}")
    if done.returncode != 0:
        raise OptionError(f"'{executable} --help' exited with {done.returncode}")
    return done.stdout + done.stderr


def known_options(help):
    return set(re.findall(r"--([A-Za-z][A-Za-z0-9]*)", help))


def options_for(config, path):
    """`options`, then every override whose pattern matches the input's path, in order."""
    merged = dict(config.get("options") or {})
    for override in config.get("overrides") or []:
        if fnmatch.fnmatch(path, override["match"]):
            merged.update(override.get("options") or {})
    return merged


def check(config, help):
    """One line naming every option SliceMesh does not have or the workflow sets itself."""
    sets = [config.get("options") or {}] + [o.get("options") or {} for o in config.get("overrides") or []]
    names = {name for options in sets for name in options}
    reserved = sorted(names & RESERVED)
    if reserved:
        raise OptionError("the workflow sets these options itself: " + ", ".join(reserved))
    unknown = sorted(names - known_options(help))
    if unknown:
        raise OptionError("SliceMesh has no option " + ", ".join(unknown) + " (see SliceMesh --help)")


def text(value):
    return "true" if value is True else "false" if value is False else str(value)


def arguments(options):
    """name: value -> --name value; true -> --name; false/None -> nothing; list -> a,b,c;
    list of lists -> the option repeated."""
    argv = []
    for name, value in options.items():
        if value is None or value is False:
            continue
        if value is True:
            argv.append("--" + name)
        elif isinstance(value, (list, tuple)) and value and all(isinstance(v, (list, tuple)) for v in value):
            for item in value:
                argv += ["--" + name, ",".join(map(text, item))]
        elif isinstance(value, (list, tuple)):
            argv += ["--" + name, ",".join(map(text, value))]
        else:
            argv += ["--" + name, text(value)]
    return argv


def splits_labels(options):
    return bool(options.get("splitLabels") or options.get("labels"))
