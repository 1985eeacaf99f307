// `brdftab generate` started by an MPI launcher (mpirun, mpiexec, srun): hands over to the
// MPI build of the command, brdftab-mpi beside this executable (src/mpi/), so that the
// single-process CLI never links MPI. Without it (MPI not found at configure time) a job of
// several ranks is refused: each rank would build every table and write the same files.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace brdftab::cli {

int (*generate_runner)(const GenerateOptions&, std::ostream&, std::ostream&) = nullptr;

namespace {

// The launcher's rank count: Open MPI, MPICH/Hydra (PMI), PMIx (Slurm's srun --mpi=pmix),
// else 0 (not launched by MPI).
long launched_ranks() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (const char* s = std::getenv(v); s && *s) return std::max(1L, std::atol(s));
  if (std::getenv("PMIX_RANK")) return 2;  // PMIx without a size variable: assume a job
  return 0;
}

}  // namespace

int exec_mpi_generate(int argc, char** argv, std::ostream& err) {
  const long ranks = launched_ranks();
  if (ranks == 0) return 0;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path mpi = ec ? std::filesystem::path() : exe.parent_path() / "brdftab-mpi";
  if (!mpi.empty() && ::access(mpi.c_str(), X_OK) == 0) {
    std::vector<char*> args(argv, argv + argc);
    args[0] = const_cast<char*>(mpi.c_str());
    args.push_back(nullptr);
    ::execv(mpi.c_str(), args.data());
    err << "brdftab generate: cannot start " << mpi.string() << "\n";
    return 1;
  }
  if (ranks == 1) return 0;  // one rank: the single-process run is the same
  err << "brdftab generate: started by an MPI launcher with " << ranks
      << " ranks, but this brdftab was built without MPI (no brdftab-mpi beside " << exe.string()
      << "): install Open MPI (libopenmpi-dev) and configure again, or run without mpirun\n";
  return 2;
}

}  // namespace brdftab::cli
