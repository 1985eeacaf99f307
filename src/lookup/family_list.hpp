#pragma once
// THE list of table families compiled into brdftab, in generation order. Adding a family
// is one line here (see docs/adding-a-family.md). For each key K the build requires, and
// fails to compile or link without:
//   brdftab::gen::K::{Config, read_config, to_json, build, test_config, narrowed, kSummary}
//                                                       generators/K.{hpp,cpp}
//   brdftab::schema::K::{kFile, kDatasets}              src/lookup/K_schema.hpp
//   brdftab::cli::K::quantities()                       src/cli/eval_K.cpp
//   brdftab::validate::K::report(ReportContext&)        validate/report_K.cpp
//   brdftab::validate::K::register_benchmarks(const BenchContext&)  validate/bench_K.cpp
//   brdftab::validate::K::pareto_quantities(const pareto::Options&)  validate/pareto_K.cpp
#define BRDFTAB_FAMILIES(X) \
  X(demo)                   \
  X(smith_gbeckmann)        \
  X(hfunc)                  \
  X(ghs_sigma_rel)          \
  X(ls)                     \
  X(fresnel)                \
  X(microfacet_albedo)      \
  X(htsg)                   \
  X(hazy_gloss)             \
  X(hp)                     \
  X(filip)
