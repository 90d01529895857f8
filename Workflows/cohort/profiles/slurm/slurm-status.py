#!/usr/bin/env python3
"""Snakemake's --cluster-status for Slurm: prints running, success or failed for a job id.
Asks sacct (where accounting is on), else scontrol (which knows a job until MinJobAge after it
ends). If Slurm cannot be asked right now, the job counts as running: Snakemake asks again."""
import subprocess
import sys

RUNNING = {"PENDING", "CONFIGURING", "RUNNING", "COMPLETING", "SUSPENDED", "REQUEUED", "RESIZING",
           "STAGE_OUT", "SIGNALING", "REQUEUE_HOLD", "REQUEUE_FED", "RESV_DEL_HOLD"}


def ask(command):
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None, ""
    return done.returncode, done.stdout + done.stderr


def state(jobid):
    code, out = ask(["sacct", "-j", jobid, "-X", "-n", "-P", "-o", "State"])
    if code == 0 and out.strip():
        return out.split()[0]
    code, out = ask(["scontrol", "show", "job", "-o", jobid])
    if code == 0:
        for field in out.split():
            if field.startswith("JobState="):
                return field.split("=", 1)[1]
    if "Invalid job id" in out:
        return "UNKNOWN"  # ended long ago and forgotten, with no accounting to say how
    return "RUNNING"


jobid = sys.argv[1].split(";")[0]  # sbatch --parsable prints id[;cluster]
s = state(jobid)
print("success" if s == "COMPLETED" else "running" if s in RUNNING else "failed")
