#!/usr/bin/env bash
# Checking builds that find what the tests miss, each in its own build folder, timed:
#   asan - AddressSanitizer + UndefinedBehaviorSanitizer build (build-asan): the whole test suite
#          (leak checking off for the viewer and MPI tests, whose Mesa and Open MPI keep memory).
#   tsan - ThreadSanitizer build (build-tsan): the tests whose names contain "threads" (the
#          multithreaded render, and any render/UI hand-off test named that way;
#          STRATA_TSAN_TESTS=. runs the whole suite), built from the test files that hold them.
#   fuzz - clang-14 libFuzzer + ASan + UBSan build (build-fuzz) of tests/fuzz: the scene-loader
#          fuzzer runs STRATA_FUZZ_RUNS executions (default 200000, at most STRATA_FUZZ_SECONDS,
#          default 180, on a loaded machine) from the seed corpus
#          tests/fuzz/corpus. A finding is saved in build-fuzz/findings/ and fails the check; turn
#          it into a case of tests/scene/test_fuzz_regressions.cpp.
# Usage: bash scripts/check.sh asan|tsan|fuzz...   (scripts/test.sh runs all three in CI)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${STRATA_JOBS:-$(nproc)}

# The checking builds compile in unity batches of 16 files per compiler run (CMake's UNITY_BUILD),
# which parse the common headers once per batch: a Release build takes 171 s instead of 394 s on
# two cores. The main build (scripts/setup.sh) batches only the front ends and the tests: the
# renderer library's files compile alone, as the bench times them, so a renderer file that lacks
# an include still fails there.
configure_and_build() {  # folder, target ("" = all), cmake arguments...
    local folder=$1 target=$2
    shift 2
    cmake -S . -B "$folder" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 "$@" >/dev/null
    cmake --build "$folder" --parallel "$jobs" ${target:+--target "$target"}
}

run_asan() {
    configure_and_build build-asan "" -DSTRATA_SANITIZE=address
    local asan=${ASAN_OPTIONS:-abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
    export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
    # Mesa (the viewer's OSMesa/EGL/llvmpipe contexts) and Open MPI keep allocations for the life of
    # the process, often from code LeakSanitizer cannot name: the tests that load them run with
    # leak checking off (address and UB checks stay on); all others run with it on.
    local thirdParty='*view*,*display*,*camera_controller*,*mpi*'
    # Two renders run in the Release suite only: the 8192x8192 one (67M paths into 4.8 GB of
    # accumulation state) and `strata bench --quick` (minutes under ASan). Neither exercises code
    # that the smaller renders here do not.
    local own=(--source-file-exclude="$thirdParty" --test-case-exclude='*8192x8192*,bench_smoke*' --order-by=name)
    # Most tests are single-threaded: the suite runs as three processes at once, the leak-checked
    # cases in two halves and the third-party ones, each writing its own log. (doctest's summary
    # counts every case that passes the filters as passed, including those outside its half.)
    local count
    count=$(build-asan/tests/strata_tests "${own[@]}" --count --no-version |
        sed -n 's/.*passing the current filters: \([0-9]*\).*/\1/p')
    local half=$(((count + 1) / 2)) status=0
    local lsan=${LSAN_OPTIONS:-suppressions=$PWD/tests/lsan.supp}
    ASAN_OPTIONS=$asan LSAN_OPTIONS=$lsan build-asan/tests/strata_tests "${own[@]}" --last="$half" \
        >build-asan/own-first.log 2>&1 &
    ASAN_OPTIONS=$asan LSAN_OPTIONS=$lsan build-asan/tests/strata_tests "${own[@]}" --first="$((half + 1))" \
        >build-asan/own-second.log 2>&1 &
    ASAN_OPTIONS=$asan:detect_leaks=0 build-asan/tests/strata_tests --source-file="$thirdParty" \
        >build-asan/third-party.log 2>&1 &
    for job in $(jobs -p); do wait "$job" || status=1; done
    cat build-asan/own-first.log build-asan/own-second.log build-asan/third-party.log
    return "$status"
}

run_tsan() {
    local cases=${STRATA_TSAN_TESTS:-threads}
    # Only the test files holding such cases are built (tests/CMakeLists.txt: STRATA_TESTS_NAMED).
    configure_and_build build-tsan "" -DSTRATA_SANITIZE=thread -DSTRATA_TESTS_NAMED="$cases"
    TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tests/tsan.supp} \
        ctest --test-dir build-tsan --output-on-failure --timeout 900 -j "$jobs" -R "$cases"
}

run_fuzz() {
    configure_and_build build-fuzz fuzz_scene_loaders -DSTRATA_FUZZ=ON -DSTRATA_BUILD_TESTS=OFF \
        -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14
    mkdir -p build-fuzz/corpus build-fuzz/findings
    # The seed corpus stays read-only; what the fuzzer learns goes to build-fuzz/corpus.
    build-fuzz/tests/fuzz/fuzz_scene_loaders -runs="${STRATA_FUZZ_RUNS:-200000}" \
        -max_total_time="${STRATA_FUZZ_SECONDS:-180}" -max_len=4096 \
        -dict=tests/fuzz/loaders.dict -artifact_prefix=build-fuzz/findings/ -print_final_stats=1 \
        build-fuzz/corpus tests/fuzz/corpus 2>&1 | grep -E "^(Done|stat::|==|SUMMARY)|ERROR|crash|leak" || true
    if compgen -G "build-fuzz/findings/*" >/dev/null; then
        echo "check fuzz: findings in build-fuzz/findings/" >&2
        return 1
    fi
}

(($#)) || { echo "usage: $0 asan|tsan|fuzz..." >&2; exit 2; }
for check in "$@"; do
    case $check in
        asan | tsan | fuzz) ;;
        *) echo "check: unknown check '$check' (use asan, tsan or fuzz)" >&2; exit 2 ;;
    esac
    start=$SECONDS
    "run_$check"
    echo "check $check: passed in $((SECONDS - start)) s" >&2
done
