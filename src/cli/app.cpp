// Command-line parsing (CLI11) for `brdftab`; the work is in cmd_*.cpp.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>

#include "cli/commands.hpp"
#include "cli/foreign_isolation.hpp"
#include "cli/quantity.hpp"
#include "lookup/default_tables.hpp"
#include "lookup/version.hpp"

namespace brdftab::cli {

// Tables to read when --tables is not given: BRDFTAB_TABLES, else ./tables, else the
// installed default tables (<prefix>/share/brdftab/tables), else the tables of the source
// tree next to the build folder the executable runs from. Reading only: generate writes
// to --out, which defaults to ./tables, never to an installed or source folder.
std::filesystem::path default_tables_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("BRDFTAB_TABLES"); env && *env) return env;
  std::error_code ec;
  if (fs::is_directory("tables", ec)) return "tables";
  if (fs::is_directory(lookup::installed_tables_dir(), ec)) return lookup::installed_tables_dir();
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && fs::is_regular_file(exe.parent_path().parent_path() / "tables" / "default.json", ec))
    return exe.parent_path().parent_path() / "tables";
  return "tables";
}

// The deprecated spelling of a subcommand's `--tables DIR` (`--out DIR`, or for `check` a
// positional DIR): hidden from --help, exclusive with `--tables`. apply() moves its value
// into the `--tables` value, with a warning.
struct DeprecatedFolder {
  std::filesystem::path* target;
  std::filesystem::path value{};
  CLI::Option* option = nullptr;
  std::string spelling{};
  void add(CLI::App* sub, const std::string& name, CLI::Option* current) {
    spelling = name;
    option = sub->add_option(name, value)->group("")->excludes(current);
  }
  void apply(std::ostream& err) const {
    if (option->count() == 0) return;
    err << "brdftab: warning: "
        << (option->get_positional() ? std::string("a positional table folder") : "option " + spelling)
        << " is deprecated, use --tables DIR\n";
    *target = value;
  }
};

int run_main(int argc, char** argv) {
  CLI::App app{"brdftab: exact numerics and HDF5 lookup tables for BRDF models"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("brdftab ") + kVersion);

  GenerateOptions gen;
  auto* g = app.add_subcommand("generate", "generate the tables a manifest lists (default: tables/default.json)");
  auto* g_manifest = g->add_option("--manifest", gen.manifest, "manifest JSON file")->check(CLI::ExistingFile);
  g->add_option("--scene", gen.scene, "scene JSON file: generate only what its materials need (docs/scenes.md)")
      ->excludes(g_manifest);
  auto* g_out = g->add_option("--tables", gen.out_dir, "table folder to write (default: tables; required with --scene)");
  DeprecatedFolder g_old{&gen.out_dir};
  g_old.add(g, "--out", g_out);
  g->add_flag("--rebuild", gen.rebuild, "rebuild every file, also those whose content key is up to date");
  g->add_option("--only", gen.only, "generate only these families")->expected(1, -1);
  g->add_option("--threads", gen.threads, "OpenMP threads, 1-1024 (default: all cores)")->check(CLI::Range(1, 1024));
  g->add_flag("--quiet,-q", gen.quiet, "no progress output");
  g->add_flag("--discard-checkpoint", gen.discard_checkpoint,
              "discard a checkpoint left by a run of another content key instead of stopping (docs/clusters.md)");
  g->add_flag("--wait", gen.wait, "if another run is writing into the output folder, wait for it (default: exit 2)");

  EvalOptions ev;
  std::string quantities;
  for (const auto& q : all_quantities()) quantities += (quantities.empty() ? "" : ", ") + q.name;
  auto* e = app.add_subcommand("eval", "evaluate a quantity for CSV rows on stdin, CSV on stdout");
  e->add_option("quantity", ev.quantity, "one of: " + quantities)->required();
  // The accepted methods come from the quantity registry: every method a quantity registers is
  // reachable (run_eval refuses a method the named quantity lacks, listing the ones it has).
  std::set<std::string> method_names;
  for (const auto& q : all_quantities())
    for (const auto& [name, m] : q.methods) method_names.insert(name);
  std::string methods_help;
  for (const auto& name : method_names) methods_help += (methods_help.empty() ? "" : " | ") + name;
  e->add_option("--method", ev.method,
                "one of the quantity's methods (default exact; `brdftab eval --help` lists all, the README per quantity): " +
                    methods_help)
      ->check(CLI::IsMember(method_names));
  e->add_option("--tables", ev.tables_dir, "table folder (default: tables)");
  e->add_option("--dataset", ev.dataset,
                 "with --method table: read this dataset instead of the default one, e.g. a compact variant "
                 "(same axes; `brdftab info FILE` lists them)");

  ValidateOptions va;
  auto* v = app.add_subcommand("validate", "accuracy report: fits and tables against exact numerics");
  v->add_option("--tables", va.tables_dir, "table folder (default: tables)");
  v->add_option("--report", va.report_dir, "report folder (default: report)");
  v->add_flag("--quiet,-q", va.quiet, "less output");
  v->add_option("--only", va.only, "run only these families' sections")->expected(1, -1);
  v->add_flag("--json", va.json, "print a JSON summary (also written to REPORT/summary.json)");

  BenchOptions be;
  auto* b = app.add_subcommand("bench", "speed against error: exact numerics, tables, fits (Google Benchmark)");
  b->add_option("--tables", be.tables_dir, "table folder (default: tables)");
  b->add_option("--report", be.report_dir, "also write benchmark JSON into this folder");
  b->add_option("--pareto", be.pareto_dir,
                "instead: write run time against error of every method (CSV + gnuplot script per quantity) into this folder");
  b->add_option("--pareto-only", be.pareto_only, "with --pareto: only these families' quantities")->expected(1, -1);
  b->allow_extras();

  std::vector<std::string> info_files;
  bool info_markdown = false, info_json = false;
  auto* i = app.add_subcommand("info", "describe the tables in an HDF5 file");
  i->add_option("file", info_files, "table file(s) (.h5)")->required();
  i->add_flag("--markdown", info_markdown, "one Markdown table row per dataset (accepts several files)");
  i->add_flag("--json", info_json, "one JSON document describing every file and table")->excludes("--markdown");

  ExportOptions ex;
  auto* x = app.add_subcommand("export", "write one table as a C++ header, .npy files, a GLSL lookup function, an OpenEXR image, a pbrt Fourier BSDF or an RGL tensor");
  x->add_option("file", ex.file, "table file (.h5); not with --model");
  x->add_option("dataset", ex.dataset, "table name (`brdftab info FILE` lists them)");
  x->add_option("--format", ex.format,
                "header | npy | glsl | exr | pbrt-fourier | rgl (default: header; glsl: rank 1-3 tables; exr: 1-D/2-D "
                "tables; pbrt-fourier: ls_brdf_modes_material_<name> only; rgl: ls_brdf_modes_material_<name> or --model)")
      ->check(CLI::IsMember({"header", "npy", "glsl", "exr", "pbrt-fourier", "rgl"}));
  x->add_option("--out", ex.out_dir, "output folder (default: .)");
  x->add_option("--model", ex.model, "--format rgl: a BRDF model (`brdftab audit --list`) instead of FILE DATASET");
  x->add_option("--params", ex.params, "with --model: NAME=VALUE,... overrides of the model's default parameters")
      ->delimiter(',');
  x->add_flag("--wait", ex.wait, "if another run is writing into the output folder, wait for it (default: exit 2)");

  VerifyOptions vf;
  auto* vfy = app.add_subcommand("verify", "re-measure each table at random off-grid points against the exact numerics; "
                                           "fail if its error exceeds the stated one");
  vfy->add_option("files", vf.files, "table files (.h5)")->required();
  vfy->add_option("--samples", vf.samples, "random points per table, 1-1000000 (default 64)")->check(CLI::Range(1, 1000000));
  vfy->add_option("--seconds", vf.seconds, "time limit per table in seconds (default 10)")->check(CLI::Range(0.01, 86400.0));
  auto* vfy_manifest = vfy->add_option("--manifest", vf.manifest, "the manifest the files were generated from")
                           ->check(CLI::ExistingFile);
  vfy->add_option("--scene", vf.scene, "the scene the files were generated from")->excludes(vfy_manifest);
  std::vector<std::filesystem::path> seal_files;
  auto* sl = app.add_subcommand("seal", "re-seal table files edited on purpose (recompute their digest); "
                                        "`verify` then re-measures their values");
  sl->add_option("files", seal_files, "table files (.h5)")->required();

  AuditCommandOptions au;
  auto* a = app.add_subcommand("audit", "BRDF audit of a model: positivity/NaN to grazing angles, reciprocity, "
                                        "albedo <= 1, continuity at parameter edges");
  a->add_option("model", au.model, "a model (see --list) or all");
  a->add_option("--params", au.params, "NAME=VALUE,... overrides of the model's default parameters")
      ->delimiter(',');
  a->add_flag("--list", au.list, "list the models and their parameters");

  PlanOptions pl;
  auto* p = app.add_subcommand("plan", "what generate would build (tables, shapes, bytes, seconds, error) and what is up to date");
  auto* p_manifest = p->add_option("--manifest", pl.manifest, "manifest JSON file")->check(CLI::ExistingFile);
  p->add_option("--scene", pl.scene, "scene JSON file")->excludes(p_manifest);
  auto* p_out = p->add_option("--tables", pl.out_dir, "also report which files in this table folder are up to date");
  DeprecatedFolder p_old{&pl.out_dir};
  p_old.add(p, "--out", p_out);
  p->add_option("--ranks", pl.ranks, "estimate the wall time on this many MPI ranks, 1-1000000 (docs/clusters.md)")
      ->check(CLI::Range(1, 1000000));
  p->add_option("--threads", pl.threads, "threads per rank for the wall time (default: this machine's cores)")
      ->check(CLI::Range(1, 1024));

  CheckOptions ck;
  auto* c = app.add_subcommand("check", "exit 1 if a file the scene or manifest needs is missing or stale in the table folder");
  auto* c_dir = c->add_option("--tables", ck.dir, "table folder to check (default: tables)");
  DeprecatedFolder c_old{&ck.dir};
  c_old.add(c, "dir", c_dir);
  auto* c_manifest = c->add_option("--manifest", ck.manifest, "manifest JSON file")->check(CLI::ExistingFile);
  c->add_option("--scene", ck.scene, "scene JSON file")->excludes(c_manifest);

  bool quantities_markdown = false;
  auto* qs = app.add_subcommand("quantities", "list every eval quantity: columns, domains, outputs, methods");
  qs->add_flag("--markdown", quantities_markdown, "as the Markdown page docs/quantities.md");

  SynthOptions sy;
  auto* s = app.add_subcommand("scene-synth", "print a synthetic scene of N materials (JSON) for measurements");
  s->add_option("materials", sy.materials, "number of materials, 1-100000")->required()->check(CLI::Range(1, 100000));
  s->add_option("--seed", sy.seed, "random seed (same scene on every platform)");
  s->add_option("--models", sy.models, "comma-separated models to cycle through (default ghs,ls)");

  bool allow_foreign = false, force = false;
  for (CLI::App* sub : {static_cast<CLI::App*>(&app), e, v, b, i, x, p, c, vfy})
    sub->add_flag("--allow-foreign", allow_foreign,
                  "read table files without a brdftab digest (each is validated in a child process first)");
  g->add_flag("--force", force, "generate tables above the pre-flight size limit (4M values)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& ok) {  // --help, --version
    return app.exit(ok);
  } catch (const CLI::ParseError& err) {
    app.exit(err);  // prints CLI11's message
    return 2;       // usage errors are bad input: exit status 2, as documented
  }
  // The library reads these switches from the environment (docs/reliability.md).
  if (allow_foreign) ::setenv("BRDFTAB_ALLOW_FOREIGN", "1", 1);
  if (force) ::setenv("BRDFTAB_GENERATE_FORCE", "1", 1);
  // Foreign files (no digest) are parsed first in a child with time and memory limits.
  install_foreign_file_isolation();
  if (ev.tables_dir.empty()) ev.tables_dir = default_tables_dir();
  if (va.tables_dir.empty()) va.tables_dir = default_tables_dir();
  if (be.tables_dir.empty()) be.tables_dir = default_tables_dir();
  if (va.report_dir.empty()) va.report_dir = "report";
  for (const auto* d : {&g_old, &p_old, &c_old}) d->apply(std::cerr);
  if (gen.out_dir.empty()) gen.out_dir = "tables";
  if (ck.dir.empty()) ck.dir = "tables";

  if (g->parsed()) {
    gen.out_given = g_out->count() > 0 || g_old.option->count() > 0;
    if (generate_runner) return generate_runner(gen, std::cout, std::cerr);
    // Started by mpirun/srun: the MPI build of the same command (brdftab-mpi beside this
    // executable) deals the rows across the ranks; this one never links MPI.
    if (const int code = exec_mpi_generate(argc, argv, std::cerr); code != 0) return code;
    return run_generate(gen, std::cout, std::cerr);
  }
  if (p->parsed()) return run_plan(pl, std::cout, std::cerr);
  if (c->parsed()) return run_check(ck, std::cout, std::cerr);
  if (s->parsed()) return run_scene_synth(sy, std::cout, std::cerr);
  if (qs->parsed()) return run_quantities(quantities_markdown, std::cout);
  if (e->parsed()) return run_eval(ev, std::cin, std::cout, std::cerr);
  if (v->parsed()) return run_validate(va, std::cout, std::cerr);
  if (b->parsed()) {
    be.benchmark_args = b->remaining();
    return run_bench(be, std::cerr);
  }
  if (a->parsed()) {
    if (au.model.empty() && !au.list) {
      std::cerr << "brdftab audit: MODEL is required (or --list)\n";
      return 2;
    }
    return run_audit(au, std::cout, std::cerr);
  }
  if (x->parsed()) return run_export(ex, std::cout, std::cerr);
  if (vfy->parsed()) return run_verify(vf, std::cout, std::cerr);
  if (sl->parsed()) return run_seal(seal_files, std::cout, std::cerr);
  if (i->parsed()) {
    if (info_json) return run_info_json({info_files.begin(), info_files.end()}, std::cout, std::cerr);
    if (info_markdown) return run_info_markdown({info_files.begin(), info_files.end()}, std::cout, std::cerr);
    int status = 0;
    for (const auto& f : info_files) status = std::max(status, run_info(f, std::cout, std::cerr));
    return status;
  }
  return 1;
}

}  // namespace brdftab::cli
