// brdftab-mpi: the brdftab command with `generate` on MPI ranks. `mpirun -np N brdftab
// generate ...` starts it (brdftab hands over to it when launched by MPI); it can be named
// directly too. Built only when CMake finds MPI.
#include <mpi.h>

#include <iostream>

#include "cli/commands.hpp"
#include "src/mpi/generate_mpi.hpp"
#include "src/mpi/mpi_row_runner.hpp"

int main(int argc, char** argv) {
  int provided = 0;
  // Only each rank's main thread calls MPI; its compute threads never do.
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    std::cerr << "brdftab generate: the MPI library does not support MPI_THREAD_FUNNELED\n";
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  brdftab::mpi::install_death_messages(rank);
  brdftab::cli::generate_runner = brdftab::mpi::run_generate_mpi;
  // A failure that some ranks only see ends the job through MPI_Abort inside; here every
  // rank has the same status.
  const int code = brdftab::cli::run_main(argc, argv);
  MPI_Finalize();
  return code;
}
