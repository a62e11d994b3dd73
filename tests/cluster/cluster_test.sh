#!/usr/bin/env bash
# rt under mpirun (docs/distributed.md), run by CTest when RT_WITH_MPI is on:
#   cluster_test.sh BIN_DIR SOURCE_DIR CASE
# CASE same-picture: 3 ranks write the single process's pixels, bit for bit;
#      killed-rank: a rank killed mid-render fails the run and leaves the outputs as they were;
#      failing-rank: a rank that cannot read the scene is named by rank 0, nothing is written;
#      other-picture: a rank started with other switches is refused;
#      other-inputs: a rank that read other scene files (same names, other bytes) is refused;
#      said-once: a bad command line, --help and --version are answered by rank 0 alone.
set -u
# Under AddressSanitizer (scripts/build-and-test-sanitized): OpenMPI's plugins, loaded with dlopen
# and unloaded at MPI_Finalize, and hwloc leave their allocations at exit; the stacks end in
# unloaded modules that no suppression can name, so leak checking is off for the ranks (every
# other ASan and UBSan check stays on).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
bin=$1
source=$2
case_name=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkdir scenes empty
cp -r "$source"/scenes/. scenes/
# A 64 x 60 window of twocubes (the cube's edge, its shadow, the checkerboard) at sample
# resolution N: small.scn (3) takes a fraction of a second, slow.scn (12, with -Dx every sample
# is taken) a few seconds, to be killed in the middle.
make_scene() {
    sed -e 's/^\$ 0 0 511 399$/$ 200 170 263 229/' -e "/^sample resolution/{n;s/.*/\$ $2/}" \
        scenes/twocubes.scn > "scenes/$1.scn"
}
make_scene small 3
make_scene slow 12

mpi=(mpirun --oversubscribe)
if [ "$(id -u)" -eq 0 ]; then
    mpi+=(--allow-run-as-root)
fi

fail() {
    echo "FAIL: $*"
    exit 1
}

# The pixel bytes of a .gro: everything after the header's 'end' line.
pixels() {
    local end
    end=$(grep -abo -m1 '^end$' "$1" | cut -d: -f1)
    tail -c +$((end + 5)) "$1"
}

case $case_name in
same-picture)
    "$bin/rt" scenes/small --seed 3 --threads 2 --quiet -p --output single.png \
        > single.txt 2> /dev/null || fail "the single render failed"
    mv small.gro single.gro
    # One row per hand-out: the most messages, every rank's rows interleaved.
    RT_CLUSTER_ROWS=1 "${mpi[@]}" -n 3 -x RT_CLUSTER_ROWS "$bin/rt" scenes/small --seed 3 \
        --threads 1 --quiet -p --output cluster.png > cluster.txt 2> err.txt || {
        cat err.txt
        fail "mpirun -n 3 failed"
    }
    # -p's ray counts: every ray of every rank, the same as one process traces.
    rays() {
        grep -E '^  [a-z][a-z ]* +[0-9]+ +[0-9]+ ' "$1"
    }
    rays single.txt | grep -q '^  all ' || fail "no ray table in rt -p's output"
    diff <(rays single.txt) <(rays cluster.txt) || fail "-p counts other rays than one process"
    cmp <(pixels single.gro) <(pixels small.gro) || fail "the .gro pixels differ"
    cmp single.png cluster.png || fail "the PNGs differ"
    [ "$(grep -c 'warning' err.txt)" -le 1 ] || fail "the warnings were printed by every rank"
    [ "$(pixels small.gro | wc -c)" -eq $((64 * 60 * 12)) ] || fail "the .gro holds the wrong size"
    # A part of the picture (rt --tile) renders the same under mpirun too.
    "$bin/rt" scenes/small --tile 2/3 --quiet 2> /dev/null || fail "the single part failed"
    mv small.part-2-of-3.gro single-part.gro
    "${mpi[@]}" -n 2 "$bin/rt" scenes/small --tile 2/3 --threads 1 --quiet 2> /dev/null ||
        fail "mpirun -n 2 --tile 2/3 failed"
    cmp <(pixels single-part.gro) <(pixels small.part-2-of-3.gro) || fail "the parts differ"
    ;;
killed-rank)
    echo "an earlier picture" > slow.gro
    echo "an earlier PNG" > out.png
    cp slow.gro before.gro
    cp out.png before.png
    "${mpi[@]}" -n 3 "$bin/rt" scenes/slow -Dx --threads 1 --quiet --output out.png \
        > out.txt 2> err.txt &
    launcher=$!
    # Rank 1, found among mpirun's children by its MPI rank, is killed once it is rendering.
    victim=""
    for _ in $(seq 100); do
        for child in $(pgrep -P "$launcher"); do
            if tr '\0' '\n' < "/proc/$child/environ" 2> /dev/null |
                grep -qx 'OMPI_COMM_WORLD_RANK=1'; then
                victim=$child
            fi
        done
        [ -n "$victim" ] && break
        sleep 0.05
    done
    [ -n "$victim" ] || fail "rank 1 never started"
    sleep 0.3
    kill -KILL "$victim"
    # mpirun kills the other ranks (SIGTERM, then SIGKILL a second later) and ends. A run that
    # has not ended within a minute hangs: what is left is shown, rt's ranks or mpirun alone.
    for _ in $(seq 600); do
        kill -0 "$launcher" 2> /dev/null || break
        sleep 0.1
    done
    if kill -0 "$launcher" 2> /dev/null; then
        cat err.txt
        ps -o pid,ppid,stat,etime,wchan:20,args --ppid "$launcher" -p "$launcher"
        left=$(pgrep -P "$launcher" | wc -l)
        kill -KILL "$launcher" $(pgrep -P "$launcher")
        wait "$launcher"
        if [ "$left" -gt 0 ]; then
            fail "$left ranks still ran a minute after rank 1 was killed"
        fi
        # Every rank has ended and mpirun itself hangs: OpenMPI's fault, not rt's. What rt
        # promises is checked all the same.
        echo "mpirun did not end a minute after its ranks did; the outputs are checked anyway"
    else
        wait "$launcher"
        status=$?
        cat err.txt
        [ "$status" -ne 0 ] || fail "mpirun exited 0 after a rank was killed"
        grep -q 'rank 1' err.txt || fail "no message names rank 1"
    fi
    cmp slow.gro before.gro || fail "the .gro was replaced"
    cmp out.png before.png || fail "the PNG was replaced"
    ;;
failing-rank)
    echo "an earlier picture" > small.gro
    cp small.gro before.gro
    # Rank 2 starts in a folder without the scene: it cannot read it.
    "${mpi[@]}" -n 2 "$bin/rt" scenes/small --threads 1 --quiet : \
        -n 1 --wdir "$work/empty" "$bin/rt" scenes/small --threads 1 --quiet 2> err.txt
    status=$?
    cat err.txt
    [ "$status" -ne 0 ] || fail "mpirun exited 0 though rank 2 failed"
    grep -q '^rt: rank 2 failed: .*small.scn' err.txt || fail "rank 0 does not name rank 2"
    cmp small.gro before.gro || fail "the .gro was replaced"
    ;;
other-picture)
    "${mpi[@]}" -n 2 "$bin/rt" scenes/small --threads 1 --quiet : \
        -n 1 "$bin/rt" scenes/small -Dd --threads 1 --quiet 2> err.txt
    status=$?
    cat err.txt
    [ "$status" -ne 0 ] || fail "mpirun exited 0 though rank 2 rendered another picture"
    grep -q "^rt: rank 2 renders another picture: 'scenes/small -Dd" err.txt ||
        fail "rank 0 does not name rank 2's switches"
    [ ! -e small.gro ] || fail "a picture was written"
    ;;
other-inputs)
    # Rank 2's folder holds the same scene with another Attributes file: same switches, other
    # picture.
    mkdir other
    cp -r scenes other/
    sed -i 's/^[$] 0.0 0.2 0.98 /$ 0.0 0.3 0.98 /' other/scenes/Attributes
    cmp -s scenes/Attributes other/scenes/Attributes && fail "the Attributes file did not change"
    "${mpi[@]}" -n 2 "$bin/rt" scenes/small --threads 1 --quiet : \
        -n 1 --wdir "$work/other" "$bin/rt" scenes/small --threads 1 --quiet 2> err.txt
    status=$?
    cat err.txt
    [ "$status" -ne 0 ] || fail "mpirun exited 0 though rank 2 read other files"
    grep -q "^rt: rank 2 read other scene files (inputs fnv1a64:" err.txt ||
        fail "rank 0 does not name rank 2's other files"
    [ ! -e small.gro ] || fail "a picture was written"
    ;;
said-once)
    # Several times: a rank that ended before rank 0 spoke would, now and then, get rank 0
    # killed before its message was out.
    for attempt in 1 2 3 4 5; do
        "${mpi[@]}" -n 3 "$bin/rt" scenes/small --threads 1 --no-such-switch > out.txt 2> err.txt
        status=$?
        cat err.txt
        [ "$status" -ne 0 ] || fail "mpirun exited 0 on a bad switch (attempt $attempt)"
        [ "$(grep -c "^rt: unknown switch '--no-such-switch'" err.txt)" -eq 1 ] ||
            fail "the bad switch is not reported exactly once (attempt $attempt)"
    done
    "${mpi[@]}" -n 3 "$bin/rt" --version > out.txt 2> err.txt || fail "mpirun rt --version failed"
    [ "$(grep -c '^rt ' out.txt)" -eq 1 ] || fail "the version is not printed exactly once"
    "${mpi[@]}" -n 3 "$bin/rt" --help > out.txt 2> err.txt || fail "mpirun rt --help failed"
    "$bin/rt" --help > single.txt
    cmp out.txt single.txt || fail "the help under mpirun is not the single process's, once"
    [ ! -e small.gro ] || fail "a picture was written"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
echo "PASS: $case_name"
