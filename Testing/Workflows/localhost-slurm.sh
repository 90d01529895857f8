#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, everything (config, munge key, state, logs, pids) under
# one folder, so a test can submit real batch jobs and leave nothing behind.
#   localhost-slurm.sh start DIR   starts munged, slurmctld and slurmd; prints the slurm.conf path
#   localhost-slurm.sh stop DIR    stops the three daemons started in DIR (by their pid files)
# Clients find the cluster through SLURM_CONF=DIR/slurm.conf. On failure `start` prints one line
# saying why on stderr, stops what it started and exits 1. Slurm's daemons need root.
set -euo pipefail
action=${1:?usage: localhost-slurm.sh start|stop DIR}
dir=$(realpath -m "${2:?usage: localhost-slurm.sh start|stop DIR}")

stop() {
  for daemon in slurmd slurmctld munged; do
    local pidfile="$dir/$daemon.pid"
    [ -s "$pidfile" ] || continue
    local pid; pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$pidfile"
  done
}

fail() { echo "localhost-slurm: $*" >&2; stop; exit 1; }

if [ "$action" = stop ]; then stop; exit 0; fi
[ "$action" = start ] || { echo "usage: localhost-slurm.sh start|stop DIR" >&2; exit 2; }

for tool in munged slurmctld slurmd sinfo; do
  command -v "$tool" >/dev/null || fail "$tool is not installed (Debian packages munge, slurm-wlm)"
done
[ "$(id -u)" -eq 0 ] || fail "slurmd must run as root to start jobs (running as $(id -un))"

# munged wants its socket's folders searchable by all but writable by none but root, its key private.
mkdir -p "$dir"/{state,spool,munge,key}
chmod 755 "$dir" "$dir/munge"
chmod 700 "$dir/key"
dd if=/dev/urandom of="$dir/key/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/key/munge.key"
socket="$dir/munge/munge.socket"
munged --socket="$socket" --key-file="$dir/key/munge.key" --pid-file="$dir/munged.pid" \
  --log-file="$dir/munged.log" --seed-file="$dir/key/munged.seed" 2>"$dir/munged.err" ||
  fail "munged did not start: $(tail -n1 "$dir/munged.err")"

# Two free TCP ports, so a Slurm already running on this machine is not disturbed.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')

host=$(hostname -s)
cpus=$(nproc)
memory=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo) # half of it, in MB
cat > "$dir/slurm.conf" <<CONF
ClusterName=localhost
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
# No cgroups, accounting or MPI: a container or CI machine has none set up.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
# Finished jobs stay visible to scontrol (the profile's status script) for 10 minutes.
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"

slurmctld -f "$SLURM_CONF" -i 2>"$dir/slurmctld.err" || fail "slurmctld did not start: $(tail -n1 "$dir/slurmctld.err")"
slurmd -f "$SLURM_CONF" 2>"$dir/slurmd.err" || fail "slurmd did not start: $(tail -n1 "$dir/slurmd.err")"

# Ready when the node is idle (30 s at most).
for _ in $(seq 60); do
  state=$(sinfo -h -N -o %t 2>/dev/null || true)
  if [ "$state" = idle ]; then echo "$SLURM_CONF"; exit 0; fi
  sleep 0.5
done
fail "node $host is not idle after 30 s (state '${state:-none}'; last slurmd log line: $(tail -n1 "$dir/slurmd.log" 2>/dev/null))"
