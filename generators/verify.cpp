#include "generators/verify.hpp"

#include <chrono>
#include <map>
#include <memory>
#include <set>

#include "generators/family.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::gen {

bool FileVerification::ok() const { return first_problem().empty(); }

std::string FileVerification::first_problem() const {
  if (!error.empty()) return error;
  for (const auto& t : tables)
    if (!t.ok) return "table '" + t.dataset + "': " + t.why;
  return "";
}

FileVerification verify_file(const std::filesystem::path& file, const std::string& family,
                             const nlohmann::json& entry, const VerifyOptions& options) {
  FileVerification out;
  const auto t0 = std::chrono::steady_clock::now();
  auto done = [&] {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  const Family* f = find_family(family);
  if (!f) {
    out.error = "unknown family '" + family + "'";
    return done();
  }
  std::map<std::string, std::unique_ptr<lookup::LoadedTable>> loaded;
  try {
    const auto vf = lookup::VerifiedFile::open(file);
    for (const auto& name : vf.list_tables()) loaded[name] = std::make_unique<lookup::LoadedTable>(vf.load_table(name));
  } catch (const std::exception& e) {
    out.error = e.what();
    return done();
  }
  VerifyRequest req;
  req.samples = options.samples;
  req.seconds_per_table = options.seconds_per_table;
  req.seed = options.seed ? options.seed
                          : static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  req.find = [&](const std::string& ds) -> const lookup::LoadedTable* {
    const auto it = loaded.find(ds);
    return it == loaded.end() ? nullptr : it->second.get();
  };
  GenerateContext ctx;
  ctx.verify = &req;
  try {
    f->build(entry, ctx);
  } catch (const std::exception& e) {
    out.error = std::string("re-measuring failed: ") + e.what();
    return done();
  }
  out.tables = std::move(req.results);
  // Every table in the file must be one the entry builds (a table added by hand has no
  // numerics to answer to).
  std::set<std::string> measured;
  for (const auto& t : out.tables) measured.insert(t.dataset);
  for (const auto& [name, t] : loaded)
    if (!measured.count(name)) {
      VerifyResult r;
      r.dataset = name;
      r.why = "its entry builds no table of this name (added to the file?)";
      out.tables.push_back(r);
    }
  return done();
}

}  // namespace brdftab::gen
