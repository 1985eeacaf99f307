#include "lookup/table_set.hpp"

#include <algorithm>

namespace brdftab::lookup {

TableSet::TableSet(std::filesystem::path dir, OpenOptions options) : dir_(std::move(dir)), options_(options) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir_, ec))
    throw TableFileError("table folder '" + dir_.string() + "' does not exist or is not a directory");
}

const LoadedTable& TableSet::get(const std::string& file, const std::string& dataset) {
  const std::string key = file + "\n" + dataset;
  std::lock_guard lock(mutex_);
  auto it = loaded_.find(key);
  if (it != loaded_.end()) return *it->second;
  auto f = files_.find(file);
  if (f == files_.end()) f = files_.emplace(file, VerifiedFile::open(dir_ / file, options_)).first;
  auto loaded = std::make_unique<LoadedTable>(f->second.load_table(dataset));
  if (!substitute_.empty() && substitute_ != dataset) {
    const auto names = f->second.list_tables();
    if (std::find(names.begin(), names.end(), substitute_) != names.end()) {
      auto chosen = std::make_unique<LoadedTable>(f->second.load_table(substitute_));
      auto axes = [](const Table& t) {
        std::string s;
        for (int d = 0; d < t.rank(); ++d) s += (d ? ", " : "") + t.axis(d).name;
        return s;
      };
      if (axes(chosen->table) != axes(loaded->table))
        throw TableFileError("table file '" + (dir_ / file).string() + "': dataset '" + substitute_ + "' has axes (" +
                             axes(chosen->table) + "), but this lookup reads '" + dataset + "' with axes (" +
                             axes(loaded->table) + ")");
      const std::string q_chosen = chosen->info.attribute_string("quantity"),
                        q_asked = loaded->info.attribute_string("quantity");
      if (q_chosen != q_asked)
        throw TableFileError("table file '" + (dir_ / file).string() + "': dataset '" + substitute_ + "' holds \"" +
                             q_chosen.substr(0, 100) + "\", but this lookup reads '" + dataset + "' holding \"" +
                             q_asked.substr(0, 100) + "\"");
      loaded = std::move(chosen);
      substituted_ = true;
    }
  }
  return *loaded_.emplace(key, std::move(loaded)).first->second;
}

void TableSet::substitute(std::string dataset) {
  std::lock_guard lock(mutex_);
  substitute_ = std::move(dataset);
}

bool TableSet::substituted() const {
  std::lock_guard lock(mutex_);
  return substituted_;
}

std::size_t TableSet::loaded_count() const {
  std::lock_guard lock(mutex_);
  return loaded_.size();
}

}  // namespace brdftab::lookup
