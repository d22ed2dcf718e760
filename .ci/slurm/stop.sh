#!/usr/bin/env bash
# Stops the daemons of .ci/slurm/start.sh (slurmd, slurmctld, munged), by their pid files.
# Jobs still running are killed with slurmd; the state under $STATE is kept (start.sh reuses it).
# `--slurm`: stop slurmd and slurmctld only, quietly (start.sh, on a changed configuration).
set -euo pipefail
STATE=${STATE:-/var/spool/chatter-slurm}
mode=${1:-}

# Sends SIGTERM to the process in pid file $2 and waits up to 10 s for it to end.
stop() {
  local name=$1 pidfile=$2 pid
  [ -s "$pidfile" ] || return 0
  pid=$(cat "$pidfile")
  if kill -0 "$pid" 2> /dev/null; then
    kill "$pid"
    for _ in $(seq 100); do
      kill -0 "$pid" 2> /dev/null || break
      sleep 0.1
    done
    if kill -0 "$pid" 2> /dev/null; then
      echo "error: $name (pid $pid) did not stop" >&2
      return 1
    fi
    echo "stop.sh: stopped $name (pid $pid)"
  elif [ "$mode" != --slurm ]; then
    echo "stop.sh: $name was not running"
  fi
}

stop slurmd "$STATE/slurmd.pid"
stop slurmctld "$STATE/slurmctld.pid"
[ "$mode" = --slurm ] || stop munged /run/munge/munged.pid
