#!/usr/bin/env bash
# ctest CohortWorkflow: the cohort workflow on one machine, on make_cohort.py's four inputs (two
# label maps, a grayscale volume, a truncated file). Run 1 is interrupted (Ctrl-C) while sub-03
# is being meshed; run 2 must mesh only sub-03 and complete the table (check_cohort.py); run 3 must
# find nothing to do.
# Usage: cohort-local-test.sh SLICEMESH WORKFLOW_DIR WORK_DIR
set -euo pipefail
slicemesh=$(realpath "$1") workflow=$(realpath "$2") work=$3
here=$(dirname "$(realpath "$0")")
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "CohortWorkflow: $*" >&2; exit 1; }

python3 "$here/make_cohort.py" bids
cat > study.yaml <<CONF
bids_dir: bids
bids_files: "*.nii*"
output: results
slicemesh: $slicemesh
overrides:
  - match: "*_T1w.nii*"
    options: {splitLabels: false, inputKind: Grayscale}
CONF
snapshots=""
if [ -n "${DISPLAY:-}" ] || command -v Xvfb >/dev/null; then snapshots=--snapshots; fi
smk() { snakemake -s "$workflow/Snakefile" --configfile study.yaml --cores 2 "$@"; }

# Run 1: SliceMesh on sub-03 is held until snakemake is interrupted.
cat > held-slicemesh <<SH
#!/bin/sh
case "\$*" in *sub-03*) touch "$work/held"; while :; do sleep 1; done ;; esac
exec "$slicemesh" "\$@"
SH
chmod +x held-slicemesh
set -m # job control: run 1 gets its own process group, which Ctrl-C would interrupt as a whole
smk --config slicemesh="$work/held-slicemesh" >run1.log 2>&1 &
run1=$!
set +m
# Snakemake's own count of finished jobs, not the status files: a status file exists a moment before
# snakemake has recorded its job as complete, and an interrupt in that moment leaves it "incomplete".
for _ in $(seq 240); do
  done_count=$(grep -c '^Finished job' run1.log || true)
  [ -e held ] && [ "$done_count" -eq 3 ] && break
  kill -0 $run1 2>/dev/null || { cat run1.log; fail "run 1 ended before sub-03 was held"; }
  sleep 0.5
done
[ -e held ] && [ "$done_count" -eq 3 ] || fail "run 1: sub-03 held: $([ -e held ] && echo yes || echo no), $done_count jobs finished after 120 s"
kill -INT -- -$run1
wait $run1 && fail "run 1 was interrupted but exited with 0"
[ ! -e results/sub-03/sub-03_T1w_status.json ] || fail "run 1 left a status file for the interrupted sub-03"
[ ! -e results/cohort.tsv ] || fail "run 1 wrote the table although interrupted"

# Run 2 resumes: only sub-03 is meshed, then the table and the summary.
smk >run2.log 2>&1 || { cat run2.log; fail "run 2 failed"; }
grep -Eq '^mesh +1( |$)' run2.log || { cat run2.log; fail "run 2 did not mesh exactly one input (sub-03)"; }
python3 "$here/check_cohort.py" results bids/expected.json $snapshots || fail "the results are wrong (above)"

# Run 3: nothing left to do.
smk >run3.log 2>&1 || { cat run3.log; fail "run 3 failed"; }
grep -q "Nothing to be done" run3.log || { cat run3.log; fail "run 3 found work to do after a complete run"; }
echo "CohortWorkflow: interrupted run resumed with one job; table, failed row and summary checked; rerun did nothing"
