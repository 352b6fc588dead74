#!/bin/sh
# LLVM's OpenMP runtime (libomp, the sanitizer build's) registers each process in
# /dev/shm/__KMP_REGISTERED_LIB_<pid>_<uid> and removes the file when the process exits. A process
# that was killed leaves it behind, and a later process that is given the same pid aborts at its
# first parallel region ("OMP: Error #15: Initializing libomp.so.5, but found unknown library
# already initialized"): on a machine whose pids have wrapped around, random tests fail. This
# removes the files of processes that no longer run (`make sanitize`, `ci-sanitize`, `ci-fuzz`).
for f in /dev/shm/__KMP_REGISTERED_LIB_*; do
  [ -e "$f" ] || continue
  pid=${f#/dev/shm/__KMP_REGISTERED_LIB_}
  pid=${pid%%_*}
  [ -d "/proc/$pid" ] || rm -f "$f"
done
