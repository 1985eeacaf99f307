#include "lookup/table_set.hpp"

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
  return *loaded_.emplace(key, std::move(loaded)).first->second;
}

std::size_t TableSet::loaded_count() const {
  std::lock_guard lock(mutex_);
  return loaded_.size();
}

}  // namespace brdftab::lookup
