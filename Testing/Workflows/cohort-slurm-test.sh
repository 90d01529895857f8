#!/usr/bin/env bash
# ctest CohortWorkflowSlurm: the cohort workflow through its Slurm profile on a one-node Slurm
# started on this machine (localhost-slurm.sh), the inputs found by a glob this time. A first run
# is interrupted and must leave no Slurm job behind; the next one must give the right results
# (check_cohort.py) from Slurm jobs that completed; a third finds nothing to do. Where Slurm cannot
# start, says why and checks a dry run instead.
# Usage: cohort-slurm-test.sh SLICEMESH WORKFLOW_DIR WORK_DIR
set -euo pipefail
slicemesh=$(realpath "$1") workflow=$(realpath "$2") work=$3
here=$(dirname "$(realpath "$0")")
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "CohortWorkflowSlurm: $*" >&2; exit 1; }

python3 "$here/make_cohort.py" bids
cat > study.yaml <<CONF
glob: "bids/**/*.nii*"
output: results
slicemesh: $slicemesh
mem_mb: 500
runtime_minutes: 10
overrides:
  - match: "*_T1w.nii*"
    options: {splitLabels: false, inputKind: Grayscale}
CONF
smk() { snakemake -s "$workflow/Snakefile" --profile "$workflow/profiles/slurm" --configfile study.yaml "$@"; }

trap '"$here/localhost-slurm.sh" stop "$work/slurm"' EXIT
if ! reason=$("$here/localhost-slurm.sh" start "$work/slurm" 2>&1 >/dev/null); then
  echo "CohortWorkflowSlurm: Slurm cannot start here (${reason#localhost-slurm: }); checking a dry run instead"
  smk -n >dry.log 2>&1 || { cat dry.log; fail "the dry run through the profile failed"; }
  grep -Eq '^mesh +4( |$)' dry.log || { cat dry.log; fail "the dry run does not plan one mesh job per input (4)"; }
  exit 0
fi
export SLURM_CONF="$work/slurm/slurm.conf"

# Run 1 is interrupted (Ctrl-C) while its jobs are held in SliceMesh: the profile's scancel must
# cancel every Slurm job it submitted.
cat > held-slicemesh <<SH
#!/bin/sh
case "\$*" in *--help*) ;; *) touch "$work/held"; while :; do sleep 1; done ;; esac
exec "$slicemesh" "\$@"
SH
chmod +x held-slicemesh
set -m # its own process group, as Ctrl-C would interrupt it
smk --config slicemesh="$work/held-slicemesh" >run0.log 2>&1 &
run0=$!
set +m
for _ in $(seq 120); do [ -e held ] && break; sleep 0.5; done
[ -e held ] || { cat run0.log; fail "no Slurm job started SliceMesh within 60 s"; }
kill -INT -- -$run0
wait $run0 && fail "the interrupted run exited with 0"
submitted=$(sed -n "s/.*with external jobid '\([0-9]*\)'.*/\1/p" run0.log)
[ -n "$submitted" ] || fail "the interrupted run submitted no job"
for job in $submitted; do
  state=$(scontrol show job -o "$job" | grep -o 'JobState=[A-Z_]*')
  [ "$state" = JobState=CANCELLED ] || fail "Slurm job $job of the interrupted run: $state, not cancelled"
done

# Run 2 does the work.
smk >run1.log 2>&1 || { cat run1.log; fail "the run through Slurm failed"; }
grep -Eq '^mesh +4( |$)' run1.log || { cat run1.log; fail "the run after the interruption did not mesh the 4 inputs"; }
snapshots=""
command -v Xvfb >/dev/null && snapshots=--snapshots
python3 "$here/check_cohort.py" results bids/expected.json $snapshots || fail "the results are wrong (above)"
jobs=$(python3 -c '
import glob, json
print(" ".join(str(json.load(open(p))["slurm_job"]) for p in sorted(glob.glob("results/**/*_status.json", recursive=True))))')
[ "$(echo "$jobs" | tr " " "\n" | grep -Ec '^[0-9]+$')" -eq 4 ] || fail "mesh jobs without a Slurm job id: $jobs"
[ "$(echo "$jobs" | tr " " "\n" | sort -u | wc -l)" -eq 4 ] || fail "not one Slurm job per input: $jobs"
for job in $jobs; do
  scontrol show job -o "$job" | grep -q "JobState=COMPLETED" || fail "Slurm job $job: $(scontrol show job -o "$job" | grep -o 'JobState=[A-Z_]*')"
  [ -s "logs/slurm/slicemesh-mesh-$job.log" ] || fail "no Slurm log for job $job"
done

smk >run2.log 2>&1 || { cat run2.log; fail "the third run failed"; }
grep -q "Nothing to be done" run2.log || { cat run2.log; fail "the third run found work to do"; }
echo "CohortWorkflowSlurm: interrupted run's jobs $(echo $submitted) cancelled; 4 mesh jobs ran as Slurm jobs $jobs; results checked; rerun did nothing"
