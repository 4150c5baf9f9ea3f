#!/usr/bin/env bash
# A single-node Slurm on loopback for the sweep tests (docs/slurm.md, "Testing against
# a local Slurm"): munged, slurmctld and slurmd, with every key, socket, state, spool,
# pid and log file inside one directory.
#
#   local_slurm.sh start DIR   start it; prints `export SLURM_CONF=...` (also in DIR/env.sh)
#   local_slurm.sh stop DIR    cancel its jobs and stop its daemons by their pids
#
# `start` exits with 77 and prints one line saying why when Slurm cannot run here
# (binaries missing, not root, a daemon fails to start); callers skip their test then.
# Needs root: munged and slurmd run as root. Writes nothing outside DIR.
set -uo pipefail

readonly SKIP=77
readonly START_TIMEOUT_S=30

skip() {
  echo "local_slurm: $*"
  exit "$SKIP"
}

usage() {
  echo "usage: $0 start|stop DIR" >&2
  exit 2
}

# A port on 127.0.0.1 nobody listens on, starting from one derived from our pid so
# two test runs on one machine start their searches far apart.
free_port() {
  local port=$1
  local tries
  for ((tries = 0; tries < 200; tries++)); do
    if [ -z "$(ss -Hltn "sport = :$port" 2>/dev/null)" ] && [ "$port" != "${2:-}" ]; then
      echo "$port"
      return 0
    fi
    port=$((port + 1))
    [ "$port" -gt 60999 ] && port=20000
  done
  return 1
}

# Running, and not a zombie: the daemons outlive `start`, so whoever adopts them reaps
# them, maybe seconds after they exit.
pid_alive() {
  local state
  [ -n "$1" ] && kill -0 "$1" 2>/dev/null || return 1
  state=$(sed -n 's/^State:[[:space:]]*\([A-Z]\).*/\1/p' "/proc/$1/status" 2>/dev/null)
  [ "$state" != Z ]
}

# Stops the daemon whose pid `start` recorded in DIR/pids/NAME, if that pid is still
# that daemon: TERM, then KILL after 5 s.
stop_pid() {
  local pidfile=$1 name pid i
  name=$(basename "$pidfile")
  [ -f "$pidfile" ] || return 0
  pid=$(cat "$pidfile")
  if pid_alive "$pid" && [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ]; then
    kill -TERM "$pid" 2>/dev/null
    for ((i = 0; i < 50; i++)); do
      pid_alive "$pid" || break
      sleep 0.1
    done
    pid_alive "$pid" && kill -KILL "$pid" 2>/dev/null
  fi
  rm -f "$pidfile"
}

stop_cluster() {
  local dir=$1 i
  if [ -f "$dir/slurm.conf" ] && [ -f "$dir/pids/slurmctld" ] &&
    pid_alive "$(cat "$dir/pids/slurmctld")"; then
    # Jobs still running would leave their slurmstepd behind the daemons.
    SLURM_CONF="$dir/slurm.conf" squeue -h -o %A 2>/dev/null |
      xargs -r env SLURM_CONF="$dir/slurm.conf" scancel --quiet 2>/dev/null
    for ((i = 0; i < 50; i++)); do
      [ -z "$(SLURM_CONF="$dir/slurm.conf" squeue -h -o %A 2>/dev/null)" ] && break
      sleep 0.1
    done
  fi
  stop_pid "$dir/pids/slurmd"
  stop_pid "$dir/pids/slurmctld"
  stop_pid "$dir/pids/munged"
}

# The last log line of a daemon that failed, for the skip reason.
last_log_line() {
  [ -f "$1" ] && grep -v -e pmix -e 'No such file or directory' "$1" | tail -n 1
}

start_cluster() {
  local dir=$1
  [ "$(id -u)" -eq 0 ] || skip "not root: munged and slurmd need root"
  local tool
  for tool in munged slurmctld slurmd sbatch squeue scontrol sinfo scancel ss; do
    command -v "$tool" >/dev/null 2>&1 ||
      skip "$tool not found: install slurm-wlm and munge (scripts/setup.sh)"
  done

  mkdir -p "$dir" || skip "cannot create $dir"
  dir=$(cd "$dir" && pwd) || skip "cannot enter $dir"
  local daemon
  for daemon in munged slurmctld slurmd; do
    if [ -f "$dir/pids/$daemon" ] && pid_alive "$(cat "$dir/pids/$daemon")"; then
      skip "a local Slurm already runs in $dir: stop it first"
    fi
  done
  mkdir -p "$dir"/{munge,state,spool,log,pids} || skip "cannot create directories in $dir"
  # munged checks that its socket directory and every parent can be searched by all.
  chmod 711 "$dir" "$dir/munge" || skip "cannot chmod $dir"

  # The munge key: 1 KiB of random bytes, readable by root only.
  local key="$dir/munge/munge.key"
  if ! dd if=/dev/urandom of="$key" bs=1024 count=1 status=none; then
    skip "cannot write the munge key"
  fi
  chmod 0400 "$key"

  local socket="$dir/munge/munge.socket"

  # The node as slurmd sees it: asking for more CPUs or memory would invalidate it.
  local hw cpus memory
  hw=$(slurmd -C 2>/dev/null | head -n 1)
  cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$hw")
  memory=$(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$hw")
  [ -n "$cpus" ] || cpus=1
  [ -n "$memory" ] || memory=1

  local ctld_port slurmd_port
  ctld_port=$(free_port $((20000 + ($$ * 2) % 40000))) || skip "no free port on 127.0.0.1"
  slurmd_port=$(free_port $((ctld_port + 1)) "$ctld_port") || skip "no free port on 127.0.0.1"

  : >"$dir/plugstack.conf"
  cat >"$dir/slurm.conf" <<EOF
# A single-node Slurm on loopback for tests, written by tests/support/local_slurm.sh.
ClusterName=corrmptest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
CommunicationParameters=NoCtldInAddrAny,NoInAddrAny
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/state/slurmctld.pid
SlurmdPidFile=$dir/spool/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
PlugStackConfig=$dir/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
MailProg=/bin/true
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=300
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$dir/slurm.conf"
  printf 'export SLURM_CONF=%q\n' "$SLURM_CONF" >"$dir/env.sh"

  munged --foreground --socket="$socket" --key-file="$key" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
    --seed-file="$dir/munge/munged.seed" </dev/null >>"$dir/log/munged.out" 2>&1 &
  echo $! >"$dir/pids/munged"
  disown

  local i
  for ((i = 0; i < 50; i++)); do
    [ -S "$socket" ] && break
    pid_alive "$(cat "$dir/pids/munged")" || break
    sleep 0.1
  done
  if [ ! -S "$socket" ]; then
    local why
    why=$(tail -n 1 "$dir/log/munged.out" 2>/dev/null)
    stop_cluster "$dir"
    skip "munged did not start: ${why:-no socket after 5 s}"
  fi

  slurmctld -D -f "$SLURM_CONF" </dev/null >>"$dir/log/slurmctld.out" 2>&1 &
  echo $! >"$dir/pids/slurmctld"
  disown
  slurmd -D -f "$SLURM_CONF" -N localhost </dev/null >>"$dir/log/slurmd.out" 2>&1 &
  echo $! >"$dir/pids/slurmd"
  disown

  local state="" deadline=$((SECONDS + START_TIMEOUT_S))
  while [ "$SECONDS" -lt "$deadline" ]; do
    for daemon in slurmctld slurmd; do
      if ! pid_alive "$(cat "$dir/pids/$daemon")"; then
        local why
        why=$(last_log_line "$dir/log/$daemon.log")
        [ -n "$why" ] || why=$(tail -n 1 "$dir/log/$daemon.out" 2>/dev/null)
        stop_cluster "$dir"
        skip "$daemon exited at start: ${why:-see $dir/log}"
      fi
    done
    state=$(sinfo -h -n localhost -o %T 2>/dev/null)
    [ "$state" = idle ] && break
    sleep 0.2
  done
  if [ "$state" != idle ]; then
    stop_cluster "$dir"
    skip "the node is not idle after ${START_TIMEOUT_S} s (state: ${state:-no answer}); see $dir/log"
  fi
  cat "$dir/env.sh"
}

[ $# -eq 2 ] || usage
case "$1" in
start) start_cluster "$2" ;;
stop)
  [ -d "$2" ] || exit 0
  stop_cluster "$(cd "$2" && pwd)"
  ;;
*) usage ;;
esac
