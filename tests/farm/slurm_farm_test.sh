#!/usr/bin/env bash
# The Slurm render farm for real: brings up a one-node cluster on this machine (munged, slurmctld
# and slurmd from Debian's munge and slurm-wlm, with a generated slurm.conf in a temporary folder),
# runs scripts/slurm-render.sh on a small flag (tests/data/end_to_end_flag.yaml) in three chunks,
# and checks that every frame is byte for byte the frame of one whole 'dinam render', that the
# movie has all 120 frames, and that each job's log says what it did and how it ended. Then the
# failures: a bad --size is refused before anything is queued, and a farm whose render tasks fail
# exits 1 naming the failed tasks and the cancelled movie. The daemons are stopped and the folder
# removed at the end, whatever happens.
#
#   tests/farm/slurm_farm_test.sh DINAM SOURCE_DIR
#
# Exits 77 (CTest: skipped) without Slurm or munge installed, or when not run as root (slurmd
# starts jobs as their user). scripts/install-deps.sh installs both, so CI runs it.
set -euo pipefail
dinam=$(realpath "$1")
source_dir=$(realpath "$2")
size=160x90

for program in munged mungekey slurmctld slurmd sbatch scontrol ffprobe; do
  if ! command -v "$program" >/dev/null; then
    echo "SKIPPED: $program is not installed (scripts/install-deps.sh installs it)"
    exit 77
  fi
done
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: a one-node Slurm cluster needs root for slurmd"
  exit 77
fi

work=$(mktemp -d /tmp/dinam-slurm-XXXXXX)
chmod 755 "$work"
started=$(date +%s.%N)
stop_cluster() {
  if [ -f "$work/slurm.conf" ]; then
    SLURM_CONF="$work/slurm.conf" scontrol shutdown >/dev/null 2>&1 || true
  fi
  for pid_file in "$work/slurmctld.pid" "$work/slurmd.pid" "$work/munge/munged.pid"; do
    if [ -f "$pid_file" ]; then
      pid=$(cat "$pid_file")
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; kill "$pid" 2>/dev/null || true; sleep 0.1; done
      kill -9 "$pid" 2>/dev/null || true
    fi
  done
}
on_exit() {
  status=$?
  if [ $status -ne 0 ]; then
    echo "--- logs ---"
    tail -n 20 "$work"/log/*.log "$work"/farm/slurm-logs/*.log 2>/dev/null || true
  fi
  stop_cluster
  rm -rf "$work"
  exit $status
}
trap on_exit EXIT

# Two free TCP ports on the loopback for slurmctld and slurmd.
free_port() {
  local port
  while :; do
    port=$(( 20000 + RANDOM % 20000 ))
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && [ "$port" != "${1:-}" ]; then
      echo "$port"
      return
    fi
  done
}
controller_port=$(free_port)
node_port=$(free_port "$controller_port")

# munge: a key of our own and a daemon on a socket of our own.
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/log"
chmod 700 "$work/munge"
mungekey --create --keyfile="$work/munge/munge.key"
munged --force --socket="$work/munge/munge.sock" --key-file="$work/munge/munge.key" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/log/munged.log" \
  --seed-file="$work/munge/munged.seed"

host=$(hostname -s)
cat >"$work/slurm.conf" <<CONF
ClusterName=dinamtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=dinam Nodes=$host Default=YES MaxTime=INFINITE State=UP OverSubscribe=YES
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -f "$SLURM_CONF" -i
slurmd -f "$SLURM_CONF"
for _ in $(seq 100); do
  [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
  sleep 0.1
done
[ "$(sinfo -h -o %T)" = idle ] || { echo "FAIL: the Slurm node did not come up"; exit 1; }
up=$(date +%s.%N)
echo "cluster up in $(awk "BEGIN { printf \"%.1f\", $up - $started }") s"

# The reference: one whole render, no cache.
"$dinam" render "$source_dir/tests/data/end_to_end_flag.yaml" -o "$work/whole" --size "$size" --movie none -q

# The farm: simulate, three chunks of 40 frames from the cache, the movie.
"$source_dir/scripts/slurm-render.sh" "$source_dir/tests/data/end_to_end_flag.yaml" --dinam "$dinam" \
  --chunk 40 --size "$size" --partition dinam --output "$work/farm" --wait
done_at=$(date +%s.%N)
echo "farm finished in $(awk "BEGIN { printf \"%.1f\", $done_at - $up }") s"

logs=$(ls "$work"/farm/slurm-logs/render-*.log | wc -l)
[ "$logs" -eq 3 ] || { echo "FAIL: expected 3 render tasks, found $logs logs"; exit 1; }
[ -f "$work/farm/cache/manifest.json" ] || { echo "FAIL: no cache"; exit 1; }
compared=0
for frame in "$work"/whole/frame_*.png; do
  name=$(basename "$frame")
  cmp -s "$frame" "$work/farm/$name" || { echo "FAIL: $name differs from the whole render's"; exit 1; }
  compared=$((compared + 1))
done
[ "$compared" -eq 120 ] || { echo "FAIL: compared $compared frames, not 120"; exit 1; }
count=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames \
  -of csv=p=0 "$work/farm/end_to_end_flag.mp4")
[ "$count" = 120 ] || { echo "FAIL: the movie has $count frames, not 120"; exit 1; }
for log in "$work"/farm/slurm-logs/*.log; do
  grep -q "ended with status 0 after" "$log" || { echo "FAIL: $log does not say how its job ended"; exit 1; }
done
grep -q "render chunk 2 of 3, frames 81-120 of 120: started on" "$work"/farm/slurm-logs/render-*_2.log ||
  { echo "FAIL: the last chunk's log does not name its frames"; exit 1; }

# A bad option is refused before anything is queued.
if "$source_dir/scripts/slurm-render.sh" "$source_dir/tests/data/end_to_end_flag.yaml" \
    --dinam "$dinam" --size 12x9000 --partition dinam --output "$work/bad" --wait 2>"$work/bad.err"; then
  echo "FAIL: --size 12x9000 was accepted"; exit 1
fi
grep -q "size takes WIDTHxHEIGHT" "$work/bad.err" || { echo "FAIL: no message for the bad size"; cat "$work/bad.err"; exit 1; }
[ -z "$(squeue -h -o %i)" ] && [ ! -d "$work/bad" ] || { echo "FAIL: a job was queued for a bad size"; exit 1; }

# Render tasks that fail: the script exits 1 and names them, and the movie cancelled after them.
cat >"$work/failing-dinam" <<WRAPPER
#!/bin/sh
if [ "\$1" = render ]; then echo "render refused for the test" >&2; exit 3; fi
exec "$dinam" "\$@"
WRAPPER
chmod 755 "$work/failing-dinam"
if "$source_dir/scripts/slurm-render.sh" "$source_dir/tests/data/end_to_end_flag.yaml" \
    --dinam "$work/failing-dinam" --chunk 60 --size "$size" --partition dinam --output "$work/failed" \
    --wait >"$work/failed.out" 2>&1; then
  echo "FAIL: the farm whose render tasks failed exited 0"; cat "$work/failed.out"; exit 1
fi
cat "$work/failed.out"
grep -q "dinam-render task 1 (job [0-9]*): FAILED, exit code 3:0" "$work/failed.out" &&
  grep -q "dinam-movie (job [0-9]*): CANCELLED" "$work/failed.out" &&
  grep -q "dinam-simulate (job [0-9]*): COMPLETED" "$work/failed.out" ||
  { echo "FAIL: the failed farm's states are not named"; exit 1; }
grep -q "render refused for the test" "$work"/failed/slurm-logs/render-*_1.log &&
  grep -q "ended with status 3 after" "$work"/failed/slurm-logs/render-*_1.log ||
  { echo "FAIL: the failed task's log does not say why and how it ended"; exit 1; }
echo "PASS: 120 frames from 3 Slurm tasks are byte-identical to one whole render; the movie has 120 frames; every log says how its job ended; a bad size is refused before queueing; failed render tasks make the script exit 1 and are named"
