// Command-line parsing (CLI11) for `brdftab`; the work is in cmd_*.cpp.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>

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

int run_main(int argc, char** argv) {
  CLI::App app{"brdftab: exact numerics and HDF5 lookup tables for BRDF models"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("brdftab ") + kVersion);

  GenerateOptions gen;
  auto* g = app.add_subcommand("generate", "generate the tables a manifest lists (default: tables/default.json)");
  auto* g_manifest = g->add_option("--manifest", gen.manifest, "manifest JSON file")->check(CLI::ExistingFile);
  g->add_option("--scene", gen.scene, "scene JSON file: generate only what its materials need (docs/scenes.md)")
      ->excludes(g_manifest);
  auto* g_out = g->add_option("--out", gen.out_dir, "output folder (default: the table folder; required with --scene)");
  g->add_flag("--rebuild", gen.rebuild, "rebuild every file, also those whose content key is up to date");
  g->add_option("--only", gen.only, "generate only these families")->expected(1, -1);
  g->add_option("--threads", gen.threads, "OpenMP threads, 1-1024 (default: all cores)")->check(CLI::Range(1, 1024));
  g->add_flag("--quiet,-q", gen.quiet, "no progress output");

  EvalOptions ev;
  std::string quantities;
  for (const auto& q : all_quantities()) quantities += (quantities.empty() ? "" : ", ") + q.name;
  auto* e = app.add_subcommand("eval", "evaluate a quantity for CSV rows on stdin, CSV on stdout");
  e->add_option("quantity", ev.quantity, "one of: " + quantities)->required();
  e->add_option("--method", ev.method, "exact | table | fit")->check(CLI::IsMember({"exact", "table", "fit"}));
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
  auto* x = app.add_subcommand("export", "write one table as a C++ header, .npy files, a GLSL snippet or an OpenEXR image");
  x->add_option("file", ex.file, "table file (.h5); not with --model");
  x->add_option("dataset", ex.dataset, "table name (`brdftab info FILE` lists them)");
  x->add_option("--format", ex.format,
                "header | npy | glsl | exr | pbrt-fourier | rgl (default: header; glsl, exr: 1-D/2-D tables; "
                "pbrt-fourier: ls_brdf_modes_material_<name> only; rgl: ls_brdf_modes_material_<name> or --model)")
      ->check(CLI::IsMember({"header", "npy", "glsl", "exr", "pbrt-fourier", "rgl"}));
  x->add_option("--out", ex.out_dir, "output folder (default: .)");
  x->add_option("--model", ex.model, "--format rgl: a BRDF model (`brdftab audit --list`) instead of FILE DATASET");
  x->add_option("--params", ex.params, "with --model: NAME=VALUE,... overrides of the model's default parameters")
      ->delimiter(',');

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
  p->add_option("--out", pl.out_dir, "also report which files in this folder are up to date");

  CheckOptions ck;
  auto* c = app.add_subcommand("check", "exit 1 if a file the scene or manifest needs is missing or stale in DIR");
  c->add_option("dir", ck.dir, "table folder")->required();
  auto* c_manifest = c->add_option("--manifest", ck.manifest, "manifest JSON file")->check(CLI::ExistingFile);
  c->add_option("--scene", ck.scene, "scene JSON file")->excludes(c_manifest);

  SynthOptions sy;
  auto* s = app.add_subcommand("scene-synth", "print a synthetic scene of N materials (JSON) for measurements");
  s->add_option("materials", sy.materials, "number of materials, 1-100000")->required()->check(CLI::Range(1, 100000));
  s->add_option("--seed", sy.seed, "random seed (same scene on every platform)");
  s->add_option("--models", sy.models, "comma-separated models to cycle through (default ghs,ls)");

  bool allow_foreign = false, force = false;
  for (CLI::App* sub : {static_cast<CLI::App*>(&app), e, v, b, i, x, p, c})
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
  if (gen.out_dir.empty()) gen.out_dir = "tables";

  if (g->parsed()) {
    gen.out_given = g_out->count() > 0;
    return run_generate(gen, std::cout, std::cerr);
  }
  if (p->parsed()) return run_plan(pl, std::cout, std::cerr);
  if (c->parsed()) return run_check(ck, std::cout, std::cerr);
  if (s->parsed()) return run_scene_synth(sy, std::cout, std::cerr);
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
