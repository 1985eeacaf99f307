// `brdftab verify FILE... [--samples N] [--seconds S] [--manifest F | --scene F]`: re-measures
// each table of each file against the exact numerics at random off-grid points
// (generators/verify.hpp), and tells a modified shipped table from the one shipped
// (lookup/shipped_tables.hpp). Exit 0: every table within its stated error; 1: a table
// fails, or a file cannot be re-measured; 2: bad input.
#include <cstdio>
#include <ostream>

#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "cli/job_source.hpp"
#include "generators/verify.hpp"
#include "lookup/bounded_read.hpp"
#include "lookup/default_tables.hpp"
#include "lookup/detail/sha256.hpp"
#include "lookup/number_format.hpp"
#include "lookup/shipped_tables.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::cli {

namespace {
namespace fs = std::filesystem;

bool same_folder(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a.empty() ? fs::path(".") : a, b, ec) && !ec;
}

// "" if not a shipped name; else "unchanged" or why it is reported.
struct ShippedCheck {
  bool shipped_name = false, modified = false, in_shipped_folder = false;
};
ShippedCheck check_shipped(const fs::path& file) {
  ShippedCheck c;
  const auto sum = lookup::shipped_table_sha256(file.filename().string());
  if (!sum) return c;
  c.shipped_name = true;
  const std::string bytes = lookup::read_regular_file(file, lookup::kMaxTableFileBytes, "table file");
  const auto d = lookup::detail::Sha256::of(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  c.modified = lookup::detail::Sha256::hex(d) != *sum;
  const fs::path dir = file.parent_path();
  c.in_shipped_folder = same_folder(dir, lookup::installed_tables_dir()) || same_folder(dir, lookup::default_tables_dir()) ||
                        same_folder(dir, default_tables_dir());
  return c;
}
}  // namespace

int run_verify(const VerifyOptions& o, std::ostream& out, std::ostream& err) {
  if (!o.scene.empty() && !o.manifest.empty()) {
    err << "brdftab verify: --scene and --manifest exclude each other\n";
    return 2;
  }
  // The entries a file may come from: the default manifest, and the one given.
  std::vector<gen::FileJob> jobs;
  {
    const auto defaults = load_jobs("verify", {}, {}, {}, err);
    if (!defaults) return 2;
    jobs = defaults->jobs;
    if (!o.scene.empty() || !o.manifest.empty()) {
      const auto given = load_jobs("verify", o.manifest, o.scene, {}, err);
      if (!given) return 2;
      jobs.insert(jobs.end(), given->jobs.begin(), given->jobs.end());
    }
  }
  gen::VerifyOptions vo;
  vo.samples = o.samples;
  vo.seconds_per_table = o.seconds;
  int status = 0;
  for (const auto& file : o.files) {
    const std::string name = escape_control(file.string());
    try {
      const ShippedCheck sc = check_shipped(file);
      if (sc.shipped_name && sc.modified && sc.in_shipped_folder) {
        out << name << ": MODIFIED: differs from the " << file.filename().string()
            << " shipped with this library (SHA-256 recorded at build time)\n";
        status = 1;
      } else if (sc.shipped_name) {
        out << name << ": " << (sc.modified ? "not the shipped " + file.filename().string() + " (a regenerated or modified copy)"
                                            : std::string("the shipped table, byte for byte"))
            << "\n";
      }
      const auto attrs = lookup::file_attributes(file);
      const auto it = attrs.find("content_key");
      const std::string* key = it == attrs.end() ? nullptr : std::get_if<std::string>(&it->second);
      const gen::FileJob* job = nullptr;
      for (const auto& j : jobs)
        if (key && j.key == *key) job = &j;
      if (!job) {
        out << name << ": FAILED: cannot re-measure: "
            << (key ? "no entry of the default manifest" + std::string(o.scene.empty() && o.manifest.empty() ? "" : " or of the one given") +
                          " has its content key (pass the --manifest or --scene it was generated from)"
                    : std::string("it has no content key"))
            << "\n";
        status = 1;
        continue;
      }
      const auto v = gen::verify_file(file, job->family, job->entry, vo);
      if (!v.error.empty()) {
        out << name << ": FAILED: " << escape_control(v.error) << "\n";
        status = 1;
        continue;
      }
      for (const auto& t : v.tables) {
        char line[160];
        std::snprintf(line, sizeof line, "%zu points, max error %.3g (stated %.3g)", t.samples, t.worst_abs, t.stated_abs);
        out << name << " " << escape_control(t.dataset) << ": " << line << ": "
            << (t.ok ? "ok" : "FAILED: " + escape_control(t.why)) << "\n";
      }
      char tail[96];
      std::snprintf(tail, sizeof tail, "%.2f s", v.seconds);
      out << name << ": " << (v.ok() ? "ok" : "FAILED") << " (" << v.tables.size() << " tables re-measured in " << tail << ")\n";
      if (!v.ok()) status = 1;
    } catch (const std::exception& e) {
      out << name << ": FAILED: " << escape_control(e.what()) << "\n";
      status = 1;
    }
  }
  return status;
}

}  // namespace brdftab::cli
