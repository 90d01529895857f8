"""The mesh rule: runs SliceMesh on one input and writes its status file (exit code, one-line
error, seconds, the files written). A failed SliceMesh run is a result, not a failed job: the
job succeeds so that the cohort table lists the input and the other inputs go on."""
import json
import os
import shlex
import shutil
import signal
import subprocess
import time

import slicemesh_options

MESH_FORMATS = ("vtp", "vtk", "stl", "ply", "obj")  # config.yaml's format


def is_progress_tag(line):
    """Slicer's progress tags (<filter-...>, </filter-...>) on stdout: left out of the log."""
    return line.startswith(("<filter-", "</filter-"))


def error_line(code, stderr):
    """SliceMesh's error is one line on stderr; warnings are lines of their own. A run ended by a
    signal (a negative code: a crash, or killed for memory) has not written one: the signal is named."""
    if code < 0:
        try:
            name = f" ({signal.Signals(-code).name})"
        except ValueError:
            name = ""
        return f"killed by signal {-code}{name}"
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    errors = [line for line in lines if not line.startswith("SliceMesh: warning:")]
    return (errors or lines or [""])[-1]


def snapshot_display(setting):
    """(take a snapshot?, start a private X server for it?). Without a display, a private Xvfb per
    job (PrivateDisplay); with neither, `true` still asks, and SliceMesh then stops with exit code 6."""
    if setting is False or str(setting).lower() == "false":
        return False, False
    if os.environ.get("DISPLAY"):
        return True, False
    if shutil.which("Xvfb"):
        return True, True
    return str(setting).lower() == "true", False


class PrivateDisplay:
    """An Xvfb for one job, for as long as the job runs. Xvfb picks a free display number itself and
    writes it to a pipe once it accepts clients (-displayfd), so jobs started together never race
    for one, and no wrapper stands between the job and SliceMesh's exit code. The server listens
    on its local socket only, with no authority file to write and clean up: no other machine can
    reach it."""

    def __enter__(self):
        read, write = os.pipe()
        try:
            self.server = subprocess.Popen(
                ["Xvfb", "-displayfd", str(write), "-screen", "0", "1024x768x24", "-nolisten", "tcp"],
                pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        finally:
            os.close(write)
        with os.fdopen(read, "rb") as pipe:
            number = pipe.readline().strip().decode()  # empty if Xvfb ended without a display
        if not number.isdigit():
            self.__exit__(None, None, None)
            raise OSError("Xvfb did not start a display")
        self.display = ":" + number
        return self

    def __exit__(self, *unused):
        self.server.terminate()
        try:
            self.server.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.server.kill()
            self.server.wait()


def remove_previous(paths):
    """A rerun starts clean: results of an earlier attempt must not pass for this one's."""
    for path in paths:
        if os.path.isdir(path):
            shutil.rmtree(path)
        elif os.path.exists(path):
            os.remove(path)


def main(snakemake):
    config, entry = snakemake.config, snakemake.params.entry
    options = snakemake.params.options
    status_path = snakemake.output.status
    base = status_path[: -len("_status.json")]
    files = {
        "model": f"{base}.{snakemake.params.format}",
        "report": f"{base}_report.json",
        "snapshot": f"{base}_snapshot.png",
        "labels": f"{base}_labels" if slicemesh_options.splits_labels(options) else None,
        "log": f"{base}.log",
    }
    # A mesh of another format is an earlier run's too.
    remove_previous([p for p in files.values() if p] + [f"{base}.{ext}" for ext in MESH_FORMATS])
    os.makedirs(os.path.dirname(base), exist_ok=True)

    executable = config.get("slicemesh", "SliceMesh")
    help = slicemesh_options.help_text(executable)
    command = [executable] + slicemesh_options.arguments(options)
    if "threads" in slicemesh_options.known_options(help):
        command += ["--threads", str(snakemake.threads)]
    command += ["--report", files["report"]]
    if files["labels"]:
        command += ["--outputDirectory", files["labels"]]
    snapshot, private_display = snapshot_display(snakemake.params.snapshot)
    if snapshot:
        command += ["--snapshot", files["snapshot"]]
    command = command + [entry["path"], files["model"]]

    began = time.monotonic()
    try:
        if private_display:
            with PrivateDisplay() as display:
                run = subprocess.run(command, capture_output=True, text=True,
                                     env=dict(os.environ, DISPLAY=display.display))
        else:
            run = subprocess.run(command, capture_output=True, text=True)
        code, stdout, stderr = run.returncode, run.stdout, run.stderr
    except OSError as error:
        code, stdout, stderr = 127, "", f"cannot run {command[0]}: {error.strerror or error}"
    seconds = time.monotonic() - began

    with open(files["log"], "w") as log:
        log.write(shlex.join(command) + "\n")
        log.writelines(line + "\n" for line in stdout.splitlines() if not is_progress_tag(line))
        log.write(stderr)

    def written(key):
        return os.path.basename(files[key]) if files[key] and os.path.exists(files[key]) else None

    status = dict(entry)
    status.update(
        exit_code=code,
        error=error_line(code, stderr) if code != 0 else "",
        seconds=round(seconds, 3),
        options=options,
        threads=snakemake.threads,
        host=os.uname().nodename,
        slurm_job=os.environ.get("SLURM_JOB_ID"),  # its log: logs/slurm/slicemesh-mesh-<id>.log
        command=command,
        files={key: written(key) for key in files},
    )
    partial = status_path + ".partial"
    with open(partial, "w") as out:
        json.dump(status, out, indent=2)
    os.replace(partial, status_path)  # last: no status file means the input is still to do


main(snakemake)  # noqa: F821 (Snakemake's script directive defines it)
