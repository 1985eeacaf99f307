#pragma once
// The `brdftab` subcommands. Each returns the process exit status:
// 0 success, 1 failure (I/O, bad file, numerics), 2 bad input (eval rows, manifest).
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace brdftab::cli {

// Default table folder to read: $BRDFTAB_TABLES, else ./tables if it exists, else the installed
// tables, else the source tree next to the build folder (see app.cpp).
std::filesystem::path default_tables_dir();

struct GenerateOptions {
  std::filesystem::path manifest;  // empty: tables/default.json of the source tree, else built-in defaults
  std::filesystem::path scene;     // a scene file instead of a manifest (docs/scenes.md)
  std::filesystem::path out_dir;
  bool out_given = false;          // --scene requires an explicit --out
  std::vector<std::string> only;
  int threads = 0;
  bool quiet = false;
  bool rebuild = false;            // rebuild files whose content key matches too
};
int run_generate(const GenerateOptions& o, std::ostream& out, std::ostream& err);

// `brdftab plan`: what generate would build (tables, shapes, bytes, estimated seconds,
// expected error) and, with --out, what in that folder is already up to date.
struct PlanOptions {
  std::filesystem::path manifest, scene, out_dir;
};
int run_plan(const PlanOptions& o, std::ostream& out, std::ostream& err);

// `brdftab check DIR`: exit 0 if every file the manifest/scene needs is in DIR and up to
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
// `info --json`: every file and table as one JSON document (cmd_info_json.cpp).
int run_info_json(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err);

struct ExportOptions {
  std::filesystem::path file;
  std::string dataset;
  std::string format = "header";  // header | npy | glsl | exr | pbrt-fourier | rgl
  std::filesystem::path out_dir = ".";
  std::string model;                // --format rgl: a model of the audit registry instead of FILE DATASET
  std::vector<std::string> params;  // NAME=VALUE overrides of the model's defaults
};
// `export`: one table as a C++ header, .npy files, a GLSL snippet or an OpenEXR image (cmd_export.cpp).
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
