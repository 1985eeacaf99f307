// `brdftab generate [--manifest FILE] [--out DIR] [--only NAME...] [--threads N] [--quiet]`
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "generators/family.hpp"
#include "generators/manifest.hpp"

namespace brdftab::cli {

namespace {

std::string human_bytes(std::size_t b) {
  char buf[32];
  if (b < 10 * 1024)
    std::snprintf(buf, sizeof buf, "%zu B", b);
  else if (b < 10 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f KB", b / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.1f MB", b / (1024.0 * 1024.0));
  return buf;
}

void print_summary(const std::vector<gen::TableSummary>& rows, double seconds, std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line, "%-22s %-22s %-14s %-8s %-7s %10s %11s %11s %8s\n", "file", "dataset", "shape",
                "storage", "interp", "size", "max_abs_err", "max_rel_err", "seconds");
  out << line;
  for (const auto& r : rows) {
    std::string shape;
    for (std::size_t d = 0; d < r.shape.size(); ++d) shape += (d ? "x" : "") + std::to_string(r.shape[d]);
    std::snprintf(line, sizeof line, "%-22s %-22s %-14s %-8s %-7s %10s %11.2e %11.2e %8.2f\n", r.file.c_str(),
                  r.dataset.c_str(), shape.c_str(), r.storage.c_str(), r.interpolation.c_str(),
                  human_bytes(r.bytes).c_str(), r.max_abs_error, r.max_rel_error, r.seconds);
    out << line;
  }
  std::snprintf(line, sizeof line, "%zu tables in %.2f s (errors measured off-grid against exact numerics)\n",
                rows.size(), seconds);
  out << line;
}

}  // namespace

int run_generate(const GenerateOptions& o, std::ostream& out, std::ostream& err) {
  std::vector<gen::ManifestEntry> entries;
  try {
    std::filesystem::path manifest = o.manifest;
    if (manifest.empty()) manifest = default_tables_dir() / "default.json";
    std::error_code ec;
    if (std::filesystem::exists(manifest, ec))
      entries = gen::load_manifest(manifest);
    else
      entries = gen::parse_manifest(gen::default_manifest());
    for (const auto& name : o.only) {
      if (!gen::find_family(name)) {
        err << "brdftab generate: --only " << name << ": unknown table family\n";
        return 2;
      }
      if (std::none_of(entries.begin(), entries.end(), [&](const auto& e) { return e.family == name; })) {
        err << "brdftab generate: --only " << name << ": the manifest has no entry for it\n";
        return 2;
      }
    }
  } catch (const gen::ManifestError& e) {
    err << "brdftab generate: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "brdftab generate: " << e.what() << "\n";
    return 1;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  StderrProgress progress(err, isatty(STDERR_FILENO) != 0, o.quiet);
  gen::GenerateContext ctx;
  ctx.out_dir = o.out_dir;
  ctx.progress = &progress;
  std::vector<gen::TableSummary> summaries;
  const auto t0 = std::chrono::steady_clock::now();
  auto selected = [&](const auto& e) {
    return o.only.empty() || std::find(o.only.begin(), o.only.end(), e.family) != o.only.end();
  };
  const auto file_count = static_cast<std::size_t>(std::count_if(entries.begin(), entries.end(), selected));
  std::size_t file_index = 0;
  for (const auto& e : entries) {
    if (!selected(e)) continue;
    progress.start_file(++file_index, file_count, e.family);
    try {
      auto s = gen::find_family(e.family)->generate(e.entry, ctx);
      summaries.insert(summaries.end(), s.begin(), s.end());
    } catch (const gen::ManifestError& ex) {
      progress.finish_line();
      err << "brdftab generate: family '" << e.family << "': " << ex.what() << "\n";
      return 2;
    } catch (const std::bad_alloc&) {
      progress.finish_line();
      err << "brdftab generate: family '" << e.family << "' failed: out of memory\n";
      return 1;
    } catch (const std::exception& ex) {
      progress.finish_line();
      err << "brdftab generate: family '" << e.family << "' failed: " << ex.what() << "\n";
      return 1;
    }
  }
  progress.finish_line();
  print_summary(summaries, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), out);
  return 0;
}

}  // namespace brdftab::cli
