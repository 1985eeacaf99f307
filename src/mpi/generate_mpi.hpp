#pragma once
// `brdftab generate` on MPI ranks (brdftab-mpi; docs/clusters.md).
#include <ostream>

#include "cli/commands.hpp"

namespace brdftab::mpi {

// Call between MPI_Init and MPI_Finalize on every rank; returns the exit status (rank 0's
// speaks for the job; a failure during the build ends the job through MPI_Abort).
int run_generate_mpi(const cli::GenerateOptions& o, std::ostream& out, std::ostream& err);

}  // namespace brdftab::mpi
