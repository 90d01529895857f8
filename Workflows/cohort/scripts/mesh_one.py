"""The mesh rule: runs SliceMesh on one input and writes its status file (exit code, one-line
error, seconds, the files written). A failed SliceMesh run is a result, not a failed job: the
job succeeds so that the cohort table lists the input and the other inputs go on."""
import json
import os
import shlex
import shutil
import subprocess
import time

import slicemesh_options


def is_progress_tag(line):
    """Slicer's progress tags (<filter-...>, </filter-...>) on stdout: left out of the log."""
    return line.startswith(("<filter-", "</filter-"))


def error_line(stderr):
    """SliceMesh's error is one line on stderr; warnings are lines of their own."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    errors = [line for line in lines if not line.startswith("SliceMesh: warning:")]
    return (errors or lines or [""])[-1]


def snapshot_wrapper(setting):
    """(take a snapshot?, command prefix). Without a display, a private Xvfb per job: xvfb-run
    -a alone races when several jobs start at once, so each starts its search at its own number."""
    if setting is False or str(setting).lower() == "false":
        return False, []
    if os.environ.get("DISPLAY"):
        return True, []
    if shutil.which("xvfb-run"):
        display = 100 + os.getpid() % 30000
        return True, ["xvfb-run", "-a", "-n", str(display), "-s", "-screen 0 1024x768x24"]
    return str(setting).lower() == "true", []  # true: SliceMesh then stops with exit code 6


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
        "model": f"{base}.{config.get('format', 'vtp')}",
        "report": f"{base}_report.json",
        "snapshot": f"{base}_snapshot.png",
        "labels": f"{base}_labels" if slicemesh_options.splits_labels(options) else None,
        "log": f"{base}.log",
    }
    remove_previous(p for p in files.values() if p)
    os.makedirs(os.path.dirname(base), exist_ok=True)

    executable = config.get("slicemesh", "SliceMesh")
    help = slicemesh_options.help_text(executable)
    command = [executable] + slicemesh_options.arguments(options)
    if "threads" in slicemesh_options.known_options(help):
        command += ["--threads", str(snakemake.threads)]
    command += ["--report", files["report"]]
    if files["labels"]:
        command += ["--outputDirectory", files["labels"]]
    snapshot, prefix = snapshot_wrapper(config.get("snapshot", "auto"))
    if snapshot:
        command += ["--snapshot", files["snapshot"]]
    command = prefix + command + [entry["path"], files["model"]]

    began = time.monotonic()
    try:
        run = subprocess.run(command, capture_output=True, text=True)
        code, stdout, stderr = run.returncode, run.stdout, run.stderr
    except OSError as error:
        code, stdout, stderr = 127, "", f"cannot run {command[0]}: {error.strerror}"
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
        error=error_line(stderr) if code != 0 else "",
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
