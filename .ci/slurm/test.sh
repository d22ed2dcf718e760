#!/usr/bin/env bash
# Runs the recipes of docs/cluster.md, read from the file itself, on a real single-node SLURM
# (.ci/slurm/start.sh) and with GNU parallel, and checks that each merged folder equals a single
# `chatter map` run of the same grid byte for byte. Needs target/release/chatter (CI builds it
# first) and root (start.sh installs and starts the daemons; GNU parallel is installed if missing).
#
# The scripts' text is not edited, and the doc's array (--array=0-31) is kept. Only the grid is
# made small, by a wrapper documented in docs/cluster.md ("How these recipes are tested"):
# `chatter` first on PATH replaces the STEPS of each axis by $STEPS and runs
# target/release/chatter, recording each call with its SLURM job and task ID (which shows that
# every shard came from its own array task).
#
# On SLURM, in three folders under a fresh work folder:
#   gaps/   map.sbatch submitted with --array=1,5,9: every task must fail, saying why, in its log;
#   steps/  map.sbatch submitted with --array=1-7:2%2 (a step and a % limit): 4 shards, merged;
#   slurm/  the doc's submission block as written: 32 shards, the merge job and its plot.
# With GNU parallel, in parallel/: the doc's block as written (8 shards, merged).
#
# At the end (pass or fail) the test's jobs still queued are cancelled, and the daemons are
# stopped if this script started them (CHATTER_SLURM_KEEP=1 keeps them). On failure the work
# folder is kept for inspection.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
doc=$repo/docs/cluster.md
bin=$repo/target/release/chatter
STEPS=8                  # cells per axis of the test grids: 64 points
TIMEOUT=${TIMEOUT:-300}  # seconds to wait for the jobs of one folder
t0=$SECONDS

say() { echo "test.sh ($((SECONDS - t0)) s): $*"; }
die() {
  echo "error: $*" >&2
  exit 1
}
[ -x "$bin" ] || die "$bin is missing: cargo build --release first"

# --- the cluster, and GNU parallel ----------------------------------------------------------------
started=
if ! { command -v scontrol > /dev/null && scontrol ping 2> /dev/null | grep -q UP; }; then
  started=1
fi
"$repo/.ci/slurm/start.sh"
if ! command -v parallel > /dev/null; then
  say "installing GNU parallel"
  apt_install() { DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends parallel > /dev/null; }
  apt_install || { apt-get update -qq && apt_install; }
fi
say "SLURM up, GNU parallel $(parallel --version | head -n 1 | cut -d ' ' -f 3)"

work=$(mktemp -d /tmp/chatter-cluster-test.XXXXXX)
ok=
cleanup() {
  # Jobs submitted from $work that are still queued (after a failure or a timeout).
  local left
  left=$(squeue -h -o '%A %Z' 2> /dev/null | awk -v w="$work" 'index($2, w) == 1 { print $1 }' | sort -u | xargs)
  if [ -n "$left" ]; then
    echo "test.sh: cancelling leftover jobs $left" >&2
    # shellcheck disable=SC2086
    scancel $left || true
  fi
  if [ -n "$started" ] && [ -z "${CHATTER_SLURM_KEEP:-}" ]; then
    "$repo/.ci/slurm/stop.sh" || true
  fi
  if [ -n "$ok" ]; then
    rm -rf "$work"
  else
    echo "test.sh: FAILED; files kept in $work" >&2
  fi
}
trap cleanup EXIT

# --- the recipes, from docs/cluster.md ------------------------------------------------------------
# Prints the $1-th fenced block (1-based) after the first line of the doc that starts with $2.
block() {
  awk -v want="$1" -v marker="$2" '
    !seen { if (index($0, marker) == 1) seen = 1; next }
    /^```/ { if (inside) { inside = 0; if (++n == want) exit } else inside = 1; next }
    inside && n + 1 == want { print }
  ' "$doc"
}
# shellcheck disable=SC2016 # the marker is the literal text `map.sbatch`
block 1 '`map.sbatch`' > "$work/map.sbatch"
# shellcheck disable=SC2016
block 2 '`map.sbatch`' > "$work/submit.sh"
block 1 '## GNU parallel' > "$work/parallel.sh"
if ! grep -q '^#SBATCH --array=' "$work/map.sbatch" || ! grep -q -- '--shard auto' "$work/map.sbatch"; then
  die "no sbatch array script after \`map.sbatch\` in $doc"
fi
grep -q 'sbatch --parsable map.sbatch' "$work/submit.sh" || die "no submission block in $doc"
grep -q '^parallel ' "$work/parallel.sh" || die "no GNU parallel block in $doc"

# Prints the task IDs of an --array range a-b[:s][%l].
range_ids() {
  local spec=${1%%%*} step=1
  [[ $spec =~ ^([0-9]+)-([0-9]+)(:([0-9]+))?$ ]] || die "--array=$1 is not a range a-b[:s][%l]"
  [ -z "${BASH_REMATCH[4]}" ] || step=${BASH_REMATCH[4]}
  seq "${BASH_REMATCH[1]}" "$step" "${BASH_REMATCH[2]}"
}
mapfile -t DOC_IDS < <(range_ids "$(sed -n 's/^#SBATCH --array=//p' "$work/map.sbatch")")

# The `chatter` wrapper: each axis `a:b:STEPS` after --rho, --kappa or --gamma gets $STEPS cells.
# A sweep whose two axes it did not shrink is refused (it would run the doc's full grid).
mkdir "$work/bin"
cat > "$work/bin/chatter" << 'EOF'
#!/usr/bin/env bash
set -euo pipefail
args=() prev='' shrunk=0
for a in "$@"; do
  case $prev in
    --rho | --kappa | --gamma) a=${a%:*}:$CHATTER_TEST_STEPS shrunk=$((shrunk + 1)) ;;
  esac
  args+=("$a")
  prev=$a
done
if [ "${1:-}" = map ] && [ "${2:-}" != merge ] && [ "$shrunk" != 2 ]; then
  echo "chatter (test wrapper): could not shrink the grid of: chatter $*" >&2
  exit 99
fi
echo "job=${SLURM_ARRAY_JOB_ID:-${SLURM_JOB_ID:--}} task=${SLURM_ARRAY_TASK_ID:--} pid=$$ ${args[*]}" >> "$CHATTER_TEST_CALLS"
exec "$CHATTER_TEST_BIN" "${args[@]}"
EOF
chmod +x "$work/bin/chatter"
export PATH="$work/bin:$PATH" CHATTER_TEST_STEPS=$STEPS CHATTER_TEST_BIN=$bin

# --- helpers --------------------------------------------------------------------------------------
# Prints the jobs (array tasks one per line) submitted from folder $1 that are still queued.
queued() { squeue -h -r -o '%i %T %Z' | awk -v w="$1" '$3 == w { print $1, $2 }'; }

# Waits until no job submitted from folder $1 is queued; on a timeout, shows the queue and fails.
wait_jobs() {
  local deadline=$((SECONDS + TIMEOUT)) q
  while q=$(queued "$1") && [ -n "$q" ]; do
    if [ $SECONDS -gt $deadline ]; then
      squeue -r
      die "jobs from $1 still queued after $TIMEOUT s: $q"
    fi
    sleep 1
  done
}

# Prints, for each task of job $1, its job ID, task ID, state and exit code (SLURM keeps ended jobs
# for MinJobAge, 300 s; there is no accounting, so no sacct).
states() {
  [ -n "$1" ] || die "states: no job ID"
  scontrol -o show job "$1" |
    awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^(JobId|ArrayTaskId|JobState|ExitCode)=/) printf "%s ", $i; print "" }' |
    sort -t = -k 3 -n
}

# Checks, in the current folder, that array job $1 ran one shard in each of its tasks $2...: task
# ID i of the list is shard k of N (its log says so), wrote parts/i, and its call was recorded
# from that task of that job; nothing else is in parts/.
shards_from_tasks() {
  local job=$1 k=0 id n
  shift
  n=$#
  [ "$(grep -c -- '--shard auto' calls)" = "$n" ] || die "not $n shard calls in $PWD/calls"
  for id in "$@"; do
    grep -q "^job=$job task=$id .*--shard auto --out parts/$id\$" calls || die "no call from task $id of job $job"
    grep -q "(shard $k/$n)" "logs/map-${job}_$id.out" || die "logs/map-${job}_$id.out is not shard $k/$n"
    [ -s "parts/$id/shard.json" ] || die "parts/$id/shard.json is missing"
    k=$((k + 1))
  done
  [ "$(ls parts)" = "$(printf '%s\n' "$@" | sort)" ] || die "parts holds $(echo parts/*), not $*"
  say "job $job: shards 0..$((n - 1)) of $n from tasks $*, each with its log"
}

# Runs the single run of the sweep of the first recorded shard call in ./calls (the same
# arguments without --shard, --out and --jobs) into ./single.
single_run() {
  local words=() a skip='' args=()
  read -r -a words < <(grep -m1 -- '--shard' calls | cut -d ' ' -f 4-)
  for a in "${words[@]}"; do
    if [ -n "$skip" ]; then
      skip=
      continue
    fi
    case $a in
      --shard | --out | --jobs) skip=1 ;;
      *) args+=("$a") ;;
    esac
  done
  "$bin" "${args[@]}" --out single > /dev/null
  say "single run: chatter ${args[*]} --out single"
}

# Compares ./map3 with ./single byte for byte, after checking that both hold the files of a map
# of the test grid.
same() {
  local rows d
  for d in map3 single; do
    if [ ! -s "$d/summary.json" ] || [ ! -s "$d/points.csv" ]; then
      die "$PWD/$d has no summary.json or points.csv"
    fi
  done
  rows=$(($(wc -l < map3/points.csv) - 1))
  [ "$rows" = $((STEPS * STEPS)) ] || die "map3/points.csv has $rows rows, not $STEPS x $STEPS"
  diff -r map3 single || die "$PWD/map3 differs from the single run"
  say "diff -r map3 single in ${PWD#"$work"/}: identical ($(find map3 -type f | wc -l) files, $rows points)"
}

# --- SLURM: submit everything, cheapest first ------------------------------------------------------
# The node runs one task of map.sbatch at a time (it asks for 2 CPUs): the refused and the small
# arrays go first.
for d in gaps steps slurm; do
  mkdir -p "$work/$d/logs" "$work/$d/parts"
  cp "$work/map.sbatch" "$work/$d/"
done
cd "$work/gaps"
gaps=$(CHATTER_TEST_CALLS=$PWD/calls sbatch --parsable --array=1,5,9 map.sbatch)
cd "$work/steps"
steps=$(CHATTER_TEST_CALLS=$PWD/calls sbatch --parsable --array=1-7:2%2 map.sbatch)
cd "$work/slurm"
rmdir logs parts # the doc's block makes them
CHATTER_TEST_CALLS=$PWD/calls bash -euo pipefail "$work/submit.sh" < /dev/null || die "the doc's submission block failed"
# Its two jobs: the array, and the merge job that depends on it (afterok:ARRAY_*).
array=$(squeue -h -o '%A %E %Z' | awk -v w="$PWD" '$3 == w && $2 == "(null)" { print $1 }' | sort -u)
merge=$(squeue -h -o '%A %E %Z' | awk -v w="$PWD" -v a="afterok:${array}_" '$3 == w && index($2, a) == 1 { print $1 }')
[[ $array =~ ^[0-9]+$ && $merge =~ ^[0-9]+$ ]] || die "the doc's block did not queue an array and a merge job: $(queued "$PWD")"
say "submitted map.sbatch with --array=1,5,9 (job $gaps), with --array=1-7:2%2 (job $steps), and the doc's block (jobs $array, $merge):"
squeue -o '%.12i %.12j %.9T %.16r %E %Z' | grep -e JOBID -e "$work" || true

# 1. --array=1,5,9: every task refused, with the message in its log, and no shard written.
wait_jobs "$work/gaps"
say "job $gaps (--array=1,5,9) ended:"
states "$gaps"
for id in 1 5 9; do
  log=logs/map-${gaps}_$id.out
  grep -H -- '--shard auto: SLURM_ARRAY_TASK_COUNT=3 but SLURM_ARRAY_TASK_MIN=1 to SLURM_ARRAY_TASK_MAX=9' "$work/gaps/$log" ||
    die "task $id of --array=1,5,9 did not refuse with the message: $(cat "$work/gaps/$log" 2> /dev/null)"
  states "$gaps" | grep -q "ArrayTaskId=$id JobState=FAILED ExitCode=2:0" || die "task $id did not fail with exit code 2"
done
[ -z "$(ls "$work/gaps/parts")" ] || die "a task of --array=1,5,9 wrote a shard"

# 2. --array=1-7:2%2: shards 0..3 of 4 from task IDs 1, 3, 5, 7; merged here.
wait_jobs "$work/steps"
cd "$work/steps"
say "job $steps (--array=1-7:2%2) ended:"
states "$steps"
shards_from_tasks "$steps" 1 3 5 7
"$bin" map merge parts/* --out map3 > /dev/null
single_run
same

# 3. The doc's block: the array, then the merge job, which also draws map3.png.
wait_jobs "$work/slurm"
cd "$work/slurm"
say "array job $array (${#DOC_IDS[@]} tasks) and merge job $merge ended:"
states "$array" | awk '{ n[$3 " " $4]++ } END { for (s in n) print n[s] " tasks: " s }'
states "$merge"
# (grep -v finds nothing when every task completed: its status 1 must not end the script.)
bad=$(states "$array" | { grep -v 'JobState=COMPLETED ExitCode=0:0' || true; } | sed 's/.*ArrayTaskId=\([0-9]*\).*/\1/' | xargs)
if [ -n "$bad" ]; then
  for id in $bad; do tail -v -n 5 "logs/map-${array}_$id.out" || true; done
  die "tasks $bad of job $array did not complete"
fi
states "$merge" | grep -q 'JobState=COMPLETED ExitCode=0:0' || die "merge job $merge: $(cat "logs/merge-$merge.out")"
shards_from_tasks "$array" "${DOC_IDS[@]}"
[ "$(grep -c "^job=$merge task=- .* map merge parts/.* --out map3\$" calls)" = 1 ] || die "no merge call from job $merge"
[ -s map3.png ] || die "the merge job drew no map3.png: $(cat "logs/merge-$merge.out")"
single_run
same

# --- GNU parallel: the doc's block, as written -----------------------------------------------------
mkdir "$work/parallel"
cd "$work/parallel"
CHATTER_TEST_CALLS=$PWD/calls bash -euo pipefail "$work/parallel.sh" < /dev/null > /dev/null
# 8 shard calls from 8 processes, shards 0..7 each once.
[ "$(grep -- '--shard' calls | cut -d ' ' -f 3 | sort -u | wc -l)" = 8 ] || die "not 8 shard processes: $(cat calls)"
for k in $(seq 0 7); do
  [ "$(grep -c -- "--shard $k/8 --out parts/$k\$" calls)" = 1 ] || die "shard $k/8 not run once: $(cat calls)"
done
say "GNU parallel: shards 0..7 of 8 from 8 processes"
single_run
same

cd "$repo"
ok=1
say "passed"
