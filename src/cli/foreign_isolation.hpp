#pragma once
// How the CLI keeps its "never a crash, never a hang" promise for foreign table files.
//
// A file with a valid brdftab digest was written by brdftab and is parsed in-process. A
// foreign file (no digest; read only with BRDFTAB_ALLOW_FOREIGN=1) may be hostile, and
// libhdf5 itself crashes on some malformed metadata. With this check installed, such a
// file's bytes (the very bytes the parent will parse, read once) are first parsed in a
// forked child process under a CPU-time limit, an address-space limit and a wall-clock
// timeout; only if the child finds every table valid does the parent parse them. A
// child that crashes, hangs or runs out of memory makes the load fail with a
// TableFileError saying so; the parent never touches those bytes with libhdf5.
#include <chrono>

namespace brdftab::cli {

struct IsolationLimits {
  std::chrono::seconds wall{20};
  unsigned cpu_seconds = 15;
  unsigned long long address_space_bytes = 4ull << 30;  // not applied under sanitizers
};
// Installs the check process-wide (lookup::set_foreign_file_check).
void install_foreign_file_isolation(IsolationLimits limits = {});

}  // namespace brdftab::cli
