#!/usr/bin/env bash
# Installs (if missing) and starts a single-node SLURM cluster on this Debian machine, for the
# tests of docs/cluster.md (.ci/slurm/test.sh). Runs as root, without systemd: munged, slurmctld
# and slurmd are started directly. Idempotent: daemons already running with the same
# configuration are kept; a changed configuration restarts them.
#
# The node is this machine as `slurmd -C` reports it (its CPUs, sockets, cores and memory), named
# `hostname -s` and reached on 127.0.0.1; one partition `ci`; no accounting (no slurmdbd, no
# sacct); all state, pid files and logs under $STATE (default /var/spool/chatter-slurm).
# .ci/slurm/stop.sh stops the daemons.
#
# Fails, printing sinfo, `scontrol show node` and the daemons' logs, if the node is not idle
# within 60 s or a one-task job (srun hostname -s) does not run on it.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
STATE=${STATE:-/var/spool/chatter-slurm}
conf=/etc/slurm/slurm.conf
t0=$SECONDS

if [ "$(id -u)" != 0 ]; then
  echo "error: $0 must run as root" >&2
  exit 1
fi

# --- Install -------------------------------------------------------------------------------------
# slurmctld and slurmd pull slurm-client, munge and the basic plugins: nothing else is needed.
# Package scripts must not try to start the daemons (no systemd here; slurmctld has no
# configuration yet): a policy-rc.d that refuses is installed for the duration if there is none.
if ! command -v slurmctld > /dev/null || ! command -v slurmd > /dev/null || ! command -v munged > /dev/null; then
  echo "start.sh: installing slurmctld, slurmd and munge"
  own_policy=
  if [ ! -e /usr/sbin/policy-rc.d ]; then
    printf '#!/bin/sh\nexit 101\n' > /usr/sbin/policy-rc.d
    chmod +x /usr/sbin/policy-rc.d
    own_policy=1
  fi
  # Without `apt-get update` first when the package lists are fresh enough (CI's first step).
  apt_install() { DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurmctld slurmd > /dev/null; }
  apt_install || { apt-get update -qq && apt_install; }
  if [ -n "$own_policy" ]; then rm -f /usr/sbin/policy-rc.d; fi
  echo "start.sh: installed in $((SECONDS - t0)) s"
fi

# Prints everything that helps to see why the cluster did not come up, then fails.
fail() {
  echo "error: $*" >&2
  for cmd in "sinfo -N -l" "scontrol show node" "scontrol ping"; do
    echo "--- $cmd" >&2
    $cmd >&2 2>&1 || true
  done
  for log in "$STATE/slurmctld.log" "$STATE/slurmd.log" /var/log/munge/munged.log; do
    echo "--- tail -n 40 $log" >&2
    tail -n 40 "$log" >&2 2>&1 || true
  done
  exit 1
}

# Whether the daemon whose pid file is $1 is running.
running() { [ -s "$1" ] && kill -0 "$(cat "$1")" 2> /dev/null; }

# --- munge ----------------------------------------------------------------------------------------
# A key (the package may have made one), then munged as the munge user.
mkdir -p /etc/munge /var/lib/munge /var/log/munge /run/munge
if [ ! -s /etc/munge/munge.key ]; then
  dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
fi
chown munge:munge /etc/munge /etc/munge/munge.key /var/lib/munge /var/log/munge /run/munge
chmod 0400 /etc/munge/munge.key
chmod 0700 /etc/munge /var/lib/munge /var/log/munge
chmod 0755 /run/munge
if ! munge -n 2> /dev/null | unmunge > /dev/null 2>&1; then
  runuser -u munge -- /usr/sbin/munged
  for _ in $(seq 50); do
    munge -n 2> /dev/null | unmunge > /dev/null 2>&1 && break
    sleep 0.1
  done
  munge -n | unmunge > /dev/null || fail "munged does not answer"
fi

# --- slurm.conf -----------------------------------------------------------------------------------
host=$(hostname -s)
# `slurmd -C` prints this machine as a NodeName line (and an UpTime line, dropped).
node=$(slurmd -C | grep '^NodeName=')
case $node in
  "NodeName=$host "*) ;;
  *) fail "slurmd -C describes node '${node%% *}', not NodeName=$host: $node" ;;
esac
mkdir -p "$STATE/slurmctld" "$STATE/slurmd" "$(dirname "$conf")"
new=$(sed -e "s|@HOST@|$host|g" -e "s|@NODE@|$node|" -e "s|@STATE@|$STATE|g" "$here/slurm.conf.in")
if [ ! -f "$conf" ] || [ "$(cat "$conf")" != "$new" ]; then
  # A new or changed configuration: restart whatever runs with the old one.
  "$here/stop.sh" --slurm
  printf '%s\n' "$new" > "$conf"
fi

# --- slurmctld, slurmd ----------------------------------------------------------------------------
# Both fork into the background once started; they read $conf.
running "$STATE/slurmctld.pid" || slurmctld || fail "slurmctld did not start"
running "$STATE/slurmd.pid" || slurmd || fail "slurmd did not start"

# Wait until the node is idle (or running or ending jobs). A node left down or drained by an
# earlier run is resumed once.
resumed=
for _ in $(seq 120); do
  state=$(sinfo -h -N -n "$host" -o %t 2> /dev/null || true)
  case $state in
    idle | mix | alloc | comp) break ;;
    down* | drain* | drng*)
      if [ -z "$resumed" ]; then
        scontrol update nodename="$host" state=resume 2> /dev/null || true
        resumed=1
      fi
      ;;
  esac
  sleep 0.5
done
case $state in
  idle | mix | alloc | comp) ;;
  *) fail "node $host is '${state:-not known}' after 60 s" ;;
esac
# A restarted slurmctld reports the node's saved state before slurmd has registered: only a job
# that runs shows that the node works.
out=$(timeout 60 srun --quiet -N1 -n1 hostname -s 2>&1) || fail "srun hostname -s failed: $out"
[ "$out" = "$host" ] || fail "srun hostname -s printed '$out', not $host"
echo "start.sh: SLURM up in $((SECONDS - t0)) s: $(sinfo -h -N -o '%N %t %c CPUs, partition %P')"
