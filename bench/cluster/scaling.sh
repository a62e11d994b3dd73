#!/usr/bin/env bash
# Cluster scaling of rt (docs/distributed.md): wall-clock seconds of one scene rendered by
#   1x1  rt --threads 1                          (one process, one thread, no MPI)
#   mpi1 mpirun -n 1 rt --threads 1              (the same under mpirun: MPI's own cost)
#   2x1  mpirun -n 2 rt --threads 1              (two ranks of one thread)
#   1x2  rt --threads 2                          (one process, two threads)
#   2x1rN mpirun -n 2 rt --threads 1 with RT_CLUSTER_ROWS=N (N rows per hand-out)
# in turns, ROUNDS times, with the load average before each round. Prints one line per run:
#   round config wall_seconds cpu_seconds load1
# (cpu: user + system of every process of the run, mpirun and its ranks included).
# Usage: bench/cluster/scaling.sh BIN_DIR SCENE_FILE ROUNDS [rt switches...]
set -euo pipefail
bin=$1
scene=$2
rounds=$3
shift 3
if [ ! -f "$scene" ]; then
    echo "scaling.sh: no scene file $scene" >&2
    exit 2
fi
mpi=(mpirun --oversubscribe)
if [ "$(id -u)" -eq 0 ]; then
    mpi+=(--allow-run-as-root)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
seconds() {
    # A failed run stops the whole script (this runs in a subshell, so it kills its parent).
    /usr/bin/time -f '%e %U %S' -o times.txt "$@" > /dev/null 2> err.txt || {
        cat err.txt >&2
        kill $$
        exit 1
    }
    read -r wall user system < times.txt
    echo "$wall $(echo "$user + $system" | bc)"
}
for round in $(seq "$rounds"); do
    load=$(cut -d' ' -f1 /proc/loadavg)
    echo "$round 1x1 $(seconds "$bin/rt" "$scene" "$@" --threads 1 --quiet -n) $load"
    echo "$round mpi1 $(seconds "${mpi[@]}" -n 1 "$bin/rt" "$scene" "$@" --threads 1 --quiet -n) $load"
    echo "$round 2x1 $(seconds "${mpi[@]}" -n 2 "$bin/rt" "$scene" "$@" --threads 1 --quiet -n) $load"
    echo "$round 1x2 $(seconds "$bin/rt" "$scene" "$@" --threads 2 --quiet -n) $load"
    for rows in 1 16; do
        echo "$round 2x1r$rows $(RT_CLUSTER_ROWS=$rows seconds "${mpi[@]}" -n 2 -x RT_CLUSTER_ROWS \
            "$bin/rt" "$scene" "$@" --threads 1 --quiet -n) $load"
    done
done
