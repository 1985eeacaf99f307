#!/usr/bin/env bash
# Sanitizer builds, each in its own build folder (never the release build/):
#   build-asan/  AddressSanitizer + UndefinedBehaviorSanitizer, the whole test suite
#   build-tsan/  ThreadSanitizer, the lookup and table-file tests
# Usage: scripts/sanitize.sh [asan|tsan|all] [extra ctest args...]   (default: all)
# Jobs: $JOBS (default 2). Exits non-zero on any failing test or sanitizer report.
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:-all}"
shift || true
jobs="${JOBS:-2}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

configure() {  # dir flags
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$2" -DCMAKE_C_FLAGS="$2" \
    -DCMAKE_EXE_LINKER_FLAGS="$2" -DCMAKE_SHARED_LINKER_FLAGS="$2" >/dev/null
}

if [[ "$what" == asan || "$what" == all ]]; then
  flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
  configure build-asan "$flags"
  cmake --build build-asan --target brdftab_tests brdftab -j"$jobs"
  # detect_leaks=0: libhdf5 keeps global free lists until exit (reported as leaks, not ours).
  export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:halt_on_error=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  ctest --test-dir build-asan -j"$jobs" -E install_and_consume --output-on-failure "$@"
fi

if [[ "$what" == tsan || "$what" == all ]]; then
  flags="-fsanitize=thread -fno-omit-frame-pointer"
  configure build-tsan "$flags"
  cmake --build build-tsan --target brdftab_tests brdftab -j"$jobs"
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
  # The lookup library and table files: interpolation, lazy table sets, the reader, the
  # crafted files (second-thread loads), the digest, the fuzz test (fork + exec).
  ctest --test-dir build-tsan -j"$jobs" --output-on-failure \
    -R "lookup|table|HDF5|crafted|SHA|digest|foreign|FIFO|fuzz|lazy|interpol|batch" "$@"
fi
