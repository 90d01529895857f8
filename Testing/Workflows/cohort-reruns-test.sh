#!/usr/bin/env bash
# ctest CohortWorkflowReruns: what meshes an input again, on make_cohort.py --reruns's inputs, whose
# voxels lie in files other than the one the glob names (a DICOM folder, a detached NRRD and MetaImage
# header), with spaces in the input and output paths. After a complete run: touching every file
# meshes nothing (small files are compared by content); a slice rewritten in place in the DICOM
# folder meshes that input again, as do new voxels behind each detached header; threads mesh
# nothing again, another format or snapshot setting everything. An input whose SliceMesh dies of a
# signal has "killed by signal 11 (SIGSEGV)" as its error, the end message counts it once, and the
# documented recovery over failed.txt (with spaces in its paths) meshes it alone.
# Usage: cohort-reruns-test.sh SLICEMESH WORKFLOW_DIR WORK_DIR
set -euo pipefail
slicemesh=$(realpath "$1") workflow=$(realpath "$2") work=$3
here=$(dirname "$(realpath "$0")")
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "CohortWorkflowReruns: $*" >&2; exit 1; }

python3 "$here/make_cohort.py" --reruns "in data"
# A structure set, a contour file or a segmentation file is named without its extension, as an image
# is (a glob over them gave results "p03 rt.dcm/p03 rt.dcm_report.json").
python3 -c 'import sys; sys.path.insert(0, sys.argv[1]); import cohort_inputs as c
names = [c.strip_extension(n) for n in ("p03 rt.dcm", "roi.json", "liver.seg.nrrd", "body.vtp", "ct.nii.gz")]
sys.exit(names != ["p03 rt", "roi", "liver", "body", "ct"])' "$workflow/scripts" || fail "input names keep their extensions"
study() { # format snapshot
  cat > study.yaml <<CONF
glob: "in data/p0*"
output: mesh results
slicemesh: $slicemesh
format: $1
snapshot: $2
CONF
}
study vtp false
smk() { snakemake -s "$workflow/Snakefile" --configfile study.yaml --cores 2 "$@"; }
# run LOG [ARGS]: a run that must succeed.
run() { local log=$1; shift; smk "$@" >"$log" 2>&1 || { cat "$log"; fail "$log: snakemake failed"; }; }
# meshed LOG: the subjects the run meshed, sorted, on one line.
meshed() { { grep -o 'output: mesh results/p0[0-9]/p0[0-9]_status.json' "$1" || true; } | cut -d/ -f2 | sort -u | tr '\n' ' ' | sed 's/ $//'; }
# expect LOG SUBJECTS WHAT: the run meshed exactly SUBJECTS ("" for none).
expect() {
  local got; got=$(meshed "$1")
  [ "$got" = "$2" ] || { cat "$1"; fail "$3: meshed '${got:-nothing}', expected '${2:-nothing}'"; }
  [ -n "$2" ] || grep -q "Nothing to be done" "$1" || { cat "$1"; fail "$3: not 'Nothing to be done'"; }
}
column() { # SUBJECT COLUMN: the value in cohort.tsv
  python3 -c 'import csv, sys
rows = [r for r in csv.DictReader(open("mesh results/cohort.tsv"), delimiter="\t") if r["subject"] == sys.argv[1]]
print(rows[0][sys.argv[2]] if len(rows) == 1 else f"{len(rows)} rows")' "$1" "$2"
}

run run1.log
expect run1.log "p01 p02 p03" "run 1"
for s in p01 p02 p03; do [ "$(column $s status)" = ok ] || { cat run1.log; fail "run 1: $s not meshed"; }; done

touch "in data"/p01/* "in data"/*
run touched.log
expect touched.log "" "every input file touched"

# A slice re-exported in place: the same name and size, other voxels (the last 400 bytes of pixel data).
python3 -c 'import sys
with open(sys.argv[1], "r+b") as f:
    f.seek(-400, 2)
    f.write(bytes(400))' "in data/p01/IM0005.dcm"
run dicom.log
expect dicom.log "p01" "a DICOM slice rewritten"

# New voxels behind the detached headers: a 12 mm cube (1.728 mL) in place of the 10 mm one.
python3 -c 'import sys
cube = bytes(1 if 4 <= min(x, y, z) and max(x, y, z) <= 15 else 0 for z in range(20) for y in range(20) for x in range(20))
for name in sys.argv[1:]:
    open(name, "wb").write(cube)' "in data/voxels-p02.raw" "in data/voxels-p03.raw"
run raw.log
expect raw.log "p02 p03" "the data files of the .nhdr and .mhd rewritten"
for s in p02 p03; do
  [ "$(column $s volume_ml)" = 1.7280 ] || fail "$s: volume $(column $s volume_ml) mL in cohort.tsv, its new voxels 1.728"
done

run threads.log --config threads=2
expect threads.log "" "threads changed"

study stl false
run format.log
expect format.log "p01 p02 p03" "format changed to stl"
[ -f "mesh results/p02/p02.stl" ] || fail "format stl: no p02.stl"
[ -z "$(find "mesh results" -name '*.vtp' -not -path '*_labels/*')" ] || fail "format stl: the .vtp meshes are still there"

study stl auto
run snapshot.log
expect snapshot.log "p01 p02 p03" "snapshot changed from false to auto"

# SliceMesh dies of SIGSEGV on p03 after a warning.
cat > crashing-slicemesh <<SH
#!/bin/sh
case "\$*" in *--help*) ;; *p03*) echo "SliceMesh: warning: something harmless" >&2; ulimit -c 0; kill -SEGV \$\$ ;; esac
exec "$slicemesh" "\$@"
SH
chmod +x crashing-slicemesh
run crash.log --config slicemesh="$work/crashing-slicemesh" --forcerun "mesh results/p03/p03_status.json"
expect crash.log "p03" "p03 forced"
[ "$(column p03 error)" = "killed by signal 11 (SIGSEGV)" ] || fail "p03 crashed: error '$(column p03 error)'"
[ "$(column p03 exit_code)" = -11 ] || fail "p03 crashed: exit code $(column p03 exit_code)"
grep -q "SliceMesh cohort: 1 of 3 inputs not meshed" crash.log || { cat crash.log; fail "the end message does not count one failed input"; }

# The recovery Cohort.md gives, with spaces in failed.txt's paths.
xargs -r -d '\n' -a "mesh results/failed.txt" \
  snakemake -s "$workflow/Snakefile" --configfile study.yaml --cores 2 --forcerun >recover.log 2>&1 ||
  { cat recover.log; fail "the recovery over failed.txt failed"; }
expect recover.log "p03" "recovery over failed.txt"
[ "$(column p03 status)" = ok ] && [ ! -s "mesh results/failed.txt" ] || fail "p03 not meshed by the recovery"
echo "CohortWorkflowReruns: DICOM slice and detached data files re-mesh their input, touch and threads do not, format and snapshot re-mesh all; a signal is named, counted once and recovered over failed.txt"
