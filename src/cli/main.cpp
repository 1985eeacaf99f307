#include "cli/commands.hpp"

int main(int argc, char** argv) { return brdftab::cli::run_main(argc, argv); }
