#pragma once
// The `brdftab` subcommands. Each returns the process exit status:
// 0 success, 1 failure (I/O, bad file, numerics), 2 bad input (eval rows, manifest).
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/job_source.hpp"
#include "generators/generate_context.hpp"

namespace brdftab::cli {

// Default table folder to read: $BRDFTAB_TABLES, else ./tables if it exists, else the installed
// tables, else the source tree next to the build folder (see app.cpp).
std::filesystem::path default_tables_dir();

struct GenerateOptions {
  std::filesystem::path manifest;  // empty: tables/default.json of the source tree, else built-in defaults
  std::filesystem::path scene;     // a scene file instead of a manifest (docs/scenes.md)
  std::filesystem::path out_dir;
  bool out_given = false;          // --scene requires an explicit --tables
  std::vector<std::string> only;
  int threads = 0;
  bool quiet = false;
  bool rebuild = false;            // rebuild files whose content key matches too
  bool discard_checkpoint = false; // start afresh over a checkpoint of another content key
  bool wait = false;               // wait for another run's lock on out_dir instead of exiting 2
};
int run_generate(const GenerateOptions& o, std::ostream& out, std::ostream& err);
// The jobs of a generate run (load_jobs, job_source.hpp), refusing --scene without --tables;
// on bad input a message on err and nullopt (exit 2). Shared with brdftab-mpi.
std::optional<JobSource> load_generate_jobs(const GenerateOptions& o, std::ostream& err);
// The table of what generate built (file, dataset, shape, size, errors, seconds).
void print_generate_summary(const std::vector<gen::TableSummary>& rows, std::ostream& out);
// Runs `generate` instead of run_generate when set: the MPI executable (brdftab-mpi) sets it.
extern int (*generate_runner)(const GenerateOptions&, std::ostream&, std::ostream&);
// Under an MPI launcher: execs brdftab-mpi beside this executable with the same arguments
// (does not return), or returns 2 after a message if there is none and the job has several
// ranks; 0 when not launched by MPI (or one rank without brdftab-mpi).
int exec_mpi_generate(int argc, char** argv, std::ostream& err);

// `brdftab plan`: what generate would build (tables, shapes, bytes, estimated seconds,
// expected error) and, with --tables, what in that folder is already up to date.
struct PlanOptions {
  std::filesystem::path manifest, scene, out_dir;
  int ranks = 1;  // wall time estimated at this many MPI ranks (each of --threads threads)
  int threads = 0;  // threads per rank (default: this machine's cores)
};
int run_plan(const PlanOptions& o, std::ostream& out, std::ostream& err);

// `brdftab check --tables DIR`: exit 0 if every file the manifest/scene needs is in DIR and up to
// date, 1 if one is missing, stale or unreadable, 2 on bad input.
struct CheckOptions {
  std::filesystem::path dir, manifest, scene;
};
int run_check(const CheckOptions& o, std::ostream& out, std::ostream& err);

// `brdftab scene-synth N`: a synthetic scene of N materials (JSON on stdout).
struct SynthOptions {
  int materials = 10;
  unsigned seed = 1;
  std::string models = "ghs,ls";
};
int run_scene_synth(const SynthOptions& o, std::ostream& out, std::ostream& err);

struct EvalOptions {
  std::string quantity;
  std::string method = "exact";
  std::filesystem::path tables_dir;
  std::string dataset;  // --dataset: with --method table, read this table instead (same axes)
};
int run_eval(const EvalOptions& o, std::istream& in, std::ostream& out, std::ostream& err);

int run_info(const std::filesystem::path& file, std::ostream& out, std::ostream& err);
// One Markdown table row per dataset of the files (file, dataset, shape, storage,
// interpolation, size, measured errors), as in the README's accuracy table.
int run_info_markdown(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err);
// `brdftab quantities [--markdown]` (cmd_quantities.cpp): the eval quantity registry.
int run_quantities(bool markdown, std::ostream& out);
// `info --json`: every file and table as one JSON document (cmd_info_json.cpp).
int run_info_json(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err);

// `brdftab verify FILE...`: re-measures each table against the exact numerics (cmd_verify.cpp).
struct VerifyOptions {
  std::vector<std::filesystem::path> files;
  std::size_t samples = 64;  // random off-grid points per table
  double seconds = 10;       // per table at most
  std::filesystem::path manifest, scene;  // where the files' entries are (besides the default manifest)
};
int run_verify(const VerifyOptions& o, std::ostream& out, std::ostream& err);
// `brdftab seal FILE...`: re-seals (recomputes the digest of) files edited on purpose (cmd_seal.cpp).
int run_seal(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err);

struct ExportOptions {
  std::filesystem::path file;
  std::string dataset;
  std::string format = "header";  // header | npy | glsl | exr | pbrt-fourier | rgl
  std::filesystem::path out_dir = ".";
  bool wait = false;  // wait for another run's lock on out_dir instead of exiting 2
  std::string model;                // --format rgl: a model of the audit registry instead of FILE DATASET
  std::vector<std::string> params;  // NAME=VALUE overrides of the model's defaults
};
// `export`: one table as a C++ header, .npy files, a GLSL lookup function or an OpenEXR image (cmd_export.cpp).
int run_export(const ExportOptions& o, std::ostream& out, std::ostream& err);

struct ValidateOptions {
  std::vector<std::string> only;  // run only these families' sections
  bool json = false;  // print the summary as JSON on stdout
  std::filesystem::path tables_dir;
  std::filesystem::path report_dir;
  bool quiet = false;
};
int run_validate(const ValidateOptions& o, std::ostream& out, std::ostream& err);

struct BenchOptions {
  std::filesystem::path tables_dir;
  std::filesystem::path report_dir;  // empty: console only
  std::vector<std::string> benchmark_args;  // passed to Google Benchmark (e.g. --benchmark_filter=...)
  std::filesystem::path pareto_dir;  // non-empty: write time-against-error CSV + gnuplot per quantity instead
  std::vector<std::string> pareto_only;  // with pareto_dir: only these families (empty: all)
};
int run_bench(const BenchOptions& o, std::ostream& err);

struct AuditCommandOptions {
  std::string model;                // a registered model (numerics/brdf_audit_model_list.hpp) or "all"
  std::vector<std::string> params;  // NAME=VALUE overrides of the model's defaults
  bool list = false;                // list the models and their parameters
};
int run_audit(const AuditCommandOptions& o, std::ostream& out, std::ostream& err);

// Parses the command line and runs the subcommand.
int run_main(int argc, char** argv);

}  // namespace brdftab::cli
